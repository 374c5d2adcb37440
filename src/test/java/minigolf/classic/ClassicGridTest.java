package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseMaps;
import minigolf.course.Course;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The bots' grid on a classic track: the ball (13 px of a 15 px tile) just fits through a corridor
 * one tile wide. With a margin of half a cell's diagonal added to its radius the grid closed every
 * such corridor (and a start tile between walls): the distance field was infinite from the start
 * on many sample tracks, and the planner had no way to the hole.
 */
class ClassicGridTest {
    static double fieldAtStart(int[] codes) throws Exception {
        Course c = TrackConverterTest.convert(codes).course();
        CourseMaps maps = new CourseMaps();
        maps.prepare(World.of(c), CancellationToken.none());
        return maps.toHole().at(c.start().x(), c.start().y());
    }

    @Test
    void aCorridorOneTileWideIsAWayAndAWallWithoutOneIsNot() throws Exception {
        int[] codes = Tracks.framed();
        // A wall across the map between the start (tile 4, 12) and the hole (tile 44, 12), with a
        // gap of one tile at row 3, far from the straight line.
        ClassicAceTest.wall(codes, 24, 1, 24, 23);
        int[] walled = codes.clone();
        Tracks.set(codes, 24, 3, TileMap.GRASS);
        double way = fieldAtStart(codes);
        assertTrue(Double.isFinite(way), "no way through the one-tile gap");
        // Round by the gap: at least start -> gap -> hole in straight lines (tile 0.25 m).
        double viaGap = 0.25 * (Math.hypot(24 - 4, 12 - 3) + Math.hypot(44 - 24, 12 - 3));
        assertTrue(way >= viaGap - 0.1 && way <= 1.2 * viaGap, way + " m, the gap's way " + viaGap + " m");
        assertEquals(Double.POSITIVE_INFINITY, fieldAtStart(walled));
    }
}
