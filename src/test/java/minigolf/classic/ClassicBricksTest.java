package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.course.Brick;
import minigolf.course.Course;
import minigolf.physics.CourseState;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The original's breakable bricks (special blocks 40..43: 4..1 hits left) as bricks: each a tile's
 * box that the ball breaks by hitting it, broken for the rest of the hole. Before, they were walls
 * for ever: a track whose only way leads through one could not be holed.
 */
class ClassicBricksTest {
    private static final double TILE = 0.25;

    /** The framed map (start (4, 12), hole (44, 12)) cut by a wall down column 20, with a brick at row 12 as the only gap. */
    static int[] brickGate(int special) {
        int[] codes = Tracks.framed();
        ClassicAceTest.wall(codes, 20, 1, 20, 23);
        Tracks.set(codes, 20, 12, TileMap.specialTile(special, PixelMap.GRASS));
        return codes;
    }

    @Test
    void everyBrickTileIsABrickWithTheHitsItShows() throws Exception {
        int[] codes = Tracks.framed();
        for (int s = 16; s <= 19; s++) Tracks.set(codes, 10 + 2 * (s - 16), 5, TileMap.specialTile(s, PixelMap.GRASS));
        TrackConverter.Converted converted = TrackConverterTest.convert(codes);
        List<Brick> bricks = converted.course().bricks();
        assertEquals(4, bricks.size());
        for (int k = 0; k < 4; k++) {
            Brick b = bricks.get(k);
            assertEquals(4 - k, b.hits(), "special " + (16 + k));
            assertEquals((10 + 2 * k) * TILE, b.min().x(), 1e-12);
            assertEquals((11 + 2 * k) * TILE, b.max().x(), 1e-12);
            assertEquals((TileMap.HEIGHT - 6) * TILE, b.min().y(), 1e-12);
            assertEquals((TileMap.HEIGHT - 5) * TILE, b.max().y(), 1e-12);
            assertEquals(0.9, b.restitution(), 0);
        }
        assertFalse(converted.files().containsKey("brick.obj"), converted.files().keySet().toString());
        assertFalse(converted.notes().stream().anyMatch(n -> n.contains("bricks")), converted.notes().toString());
    }

    /**
     * The bots' map: the standing brick closes the only gap to the ball, but the distance field leads
     * through it at a cost (DistanceField.BRICK_COST: about 5 m to cross a brick tile); broken, the
     * way is the plain 40 tiles. Before, the field had no way at all (infinite: the planner wandered).
     */
    @Test
    void theBotsMapLeadsThroughABrickAtACostAndOpensWhereItBroke() throws Exception {
        World world = World.of(TrackConverterTest.convert(brickGate(19)).course());
        Course c = world.course();
        double sx = c.start().x(), sy = c.start().y();
        assertTrue(minigolf.bot.map.CourseGrid.isBlocked(world, 20.5 * TILE, (TileMap.HEIGHT - 12.5) * TILE), "the brick blocks a ball");
        CourseMaps maps = new CourseMaps();
        maps.prepare(world, CancellationToken.none());
        double standing = maps.toHole().at(sx, sy);
        maps.prepare(world.withState(CourseState.of(c, new int[]{0})), CancellationToken.none());
        double broken = maps.toHole().at(sx, sy);
        assertFalse(minigolf.bot.map.CourseGrid.isBlocked(world.withState(CourseState.of(c, new int[]{0})), 20.5 * TILE,
                (TileMap.HEIGHT - 12.5) * TILE), "broken: open");
        // 40 tiles straight along row 12.
        assertTrue(broken >= 40 * TILE - 1e-9 && broken < 40 * TILE * 1.05, "open once broken: " + broken);
        // Standing: the crossing of 0.25 m + 2 radii (0.217 m) costs 11 times its length (to a cell
        // of 0.05 m: 14.5 m against 14.67 when written).
        double crossing = TILE + 2 * c.physics().ballRadius();
        double cell = 0.05 * (1 + minigolf.bot.map.DistanceField.BRICK_COST);
        assertEquals(broken + minigolf.bot.map.DistanceField.BRICK_COST * crossing, standing, cell);
    }

    /** The planner plays through the one-hit brick and holes out; with the brick a wall (before) it could not. */
    @Test
    void thePlannerHolesATrackWhoseOnlyWayIsThroughABrick() throws Exception {
        World world = World.of(TrackConverterTest.convert(brickGate(19)).course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed(), r.strokes() + " strokes, holed " + r.holed());
        assertTrue(r.strokes() <= 4, r.strokes() + " strokes");
    }

    /**
     * A full brick (4 hits) as the only way: the planner plays along its distance field, which leads
     * through the brick, breaks it in a few strokes (a hard putt may bounce off it more than once) and
     * holes out (3 strokes at 8c2088c; 4 at eaaebc2, where the field leads through the brick). With the
     * brick a wall (before) no stroke could hole.
     */
    @Test
    void thePlannerBreaksAFullBrick() throws Exception {
        World world = World.of(TrackConverterTest.convert(brickGate(16)).course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed() && r.strokes() <= 5, r.strokes() + " strokes, holed " + r.holed());
        assertEquals(0, r.shots().get(r.shots().size() - 1).result().state().hitsLeft(0));
    }
}
