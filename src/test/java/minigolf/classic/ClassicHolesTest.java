package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Several holes on one track (18 of the 177 sample tracks have 2 to 10): in the original any hole
 * ends the stroke. Before, only the first (row by row) was a hole here and the others were plain
 * ground: a ball rolling over one rolled on, and a track whose first hole is cut off could not be
 * holed at all.
 */
class ClassicHolesTest {
    private static final double TILE = 0.25;

    /** The framed map (start (4, 12), hole (44, 12)) with a second hole at (12, 20), below the first in row order. */
    private static int[] twoHoles() {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 12, 20, TileMap.specialTile(1, PixelMap.GRASS));
        return codes;
    }

    private static double centre(int tile) {
        return (tile + 0.5) * TILE;
    }

    private static double centreY(int row) {
        return (TileMap.HEIGHT - row - 0.5) * TILE;
    }

    @Test
    void everyHoleTileIsAHoleTheFirstCarriesTheFlag() throws Exception {
        TrackConverter.Converted converted = TrackConverterTest.convert(twoHoles());
        Course c = converted.course();
        assertEquals(centre(44), c.hole().position().x(), 1e-12);
        assertEquals(centreY(12), c.hole().position().y(), 1e-12);
        assertEquals(1, c.extraHoles().size());
        Hole second = c.extraHoles().get(0);
        assertEquals(centre(12), second.position().x(), 1e-12);
        assertEquals(centreY(20), second.position().y(), 1e-12);
        assertEquals(c.hole().radius(), second.radius(), 0);
        assertEquals(c.hole().rule(), second.rule());
        assertEquals(c.hole().captureSpeed(), second.captureSpeed());
        assertFalse(converted.notes().stream().anyMatch(n -> n.startsWith("holes:")), converted.notes().toString());
    }

    /** A slow putt straight over the second hole drops there; on the one-hole map the same putt rolls on and stops. */
    @Test
    void aSlowPuttOverTheSecondHoleDropsThere() throws Exception {
        World two = World.of(TrackConverterTest.convert(twoHoles()).course());
        World one = World.of(TrackConverterTest.convert(Tracks.framed()).course());
        Hole second = two.course().extraHoles().get(0);
        // From 1 m left of the second hole, rightwards, fast enough to roll 2 m on the grass (v^2 = 2 mu g d).
        double x = second.position().x() - 1, y = second.position().y();
        double mu = two.physics().kineticFriction(), g = two.physics().gravity();
        double v = Math.sqrt(2 * mu * g * 2);
        assertTrue(v < second.effectiveCaptureSpeed() * 4, "a putt the cup can take over its centre: " + v);
        ShotResult dropped = new Simulator(two, SimulationSettings.DEFAULT).simulate(x, y, v, 0);
        assertEquals(Outcome.HOLED, dropped.outcome(), dropped.toString());
        assertEquals(second.position().x(), dropped.endX(), second.radius());
        ShotResult rolledOn = new Simulator(one, SimulationSettings.DEFAULT).simulate(x, y, v, 0);
        assertEquals(Outcome.STOPPED, rolledOn.outcome(), rolledOn.toString());
        assertTrue(rolledOn.endX() > second.position().x() + 0.5, "rolled on past the tile: " + rolledOn);
    }

    /** The bots' distance field leads to the nearest hole: 0 at either hole, the nearer one's distance between. */
    @Test
    void theDistanceFieldMeasuresToTheNearestHole() throws Exception {
        World two = World.of(TrackConverterTest.convert(twoHoles()).course());
        CourseMaps maps = new CourseMaps();
        maps.prepare(two, CancellationToken.none());
        Hole main = two.hole(), second = two.course().extraHoles().get(0);
        assertEquals(0, maps.toHole().at(main.position().x(), main.position().y()), 1e-9);
        assertEquals(0, maps.toHole().at(second.position().x(), second.position().y()), 1e-9);
        // The start is 8 tiles across and 8 down from the second hole (2.83 m straight), 40 tiles from the first.
        double fromStart = maps.toHole().at(two.course().start().x(), two.course().start().y());
        assertTrue(fromStart >= Math.hypot(2, 2) - 1e-9 && fromStart < 3.5, "to the second hole: " + fromStart);
        var path = maps.toHole().path(two.course().start().x(), two.course().start().y());
        double[] last = path.get(path.size() - 1);
        assertEquals(second.position().x(), last[0], 1e-12);
        assertEquals(second.position().y(), last[1], 1e-12);
    }

    /**
     * The first hole walled in all round, the second open: the planner holes the second. Before, with
     * only the first a hole, no stroke could hole out (10 strokes, not holed).
     */
    @Test
    void theFirstHoleWalledInThePlannerHolesTheSecond() throws Exception {
        int[] codes = twoHoles();
        ClassicAceTest.wall(codes, 42, 10, 46, 10);
        ClassicAceTest.wall(codes, 42, 14, 46, 14);
        ClassicAceTest.wall(codes, 42, 10, 42, 14);
        ClassicAceTest.wall(codes, 46, 10, 46, 14);
        World world = World.of(TrackConverterTest.convert(codes).course());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed() && r.strokes() <= 2, r.strokes() + " strokes, holed " + r.holed());
        Hole second = world.course().extraHoles().get(0);
        ShotResult last = r.shots().get(r.shots().size() - 1).result();
        assertEquals(Outcome.HOLED, last.outcome());
        assertEquals(second.position().x(), last.endX(), second.radius() + 1e-9);
        assertEquals(second.position().y(), last.endY(), second.radius() + 1e-9);
    }
}
