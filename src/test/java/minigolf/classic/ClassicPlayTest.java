package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.Course;
import minigolf.physics.Landing;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Imported tracks play by the original's rules: the hole, water, acid and shallow water. */
class ClassicPlayTest {
    static Simulator simulator(int[] codes) throws TrackFormatException {
        Course c = TrackConverterTest.convert(codes).course();
        return new Simulator(World.of(c), SimulationSettings.DEFAULT);
    }

    static int[] strip(int element) {
        int[] codes = Tracks.framed();
        for (int y = 1; y < 24; y++) {
            for (int x = 20; x <= 22; x++) Tracks.set(codes, x, y, TileMap.elementTile(0, element, element));
        }
        return codes;
    }

    static ShotResult east(Simulator s, double fromX, double speed) {
        Course c = s.world().course();
        return s.simulate(fromX, c.start().y(), speed, 0);
    }

    @Test
    void aStraightShotDrops() throws Exception {
        Simulator s = simulator(Tracks.framed());
        Course c = s.world().course();
        ShotResult r = east(s, c.start().x(), 0.8 * c.physics().maxSpeed());
        assertEquals(Outcome.HOLED, r.outcome());
    }

    @Test
    void waterEndsTheStrokeAndTheBallGoesBackWithoutPenalty() throws Exception {
        Simulator s = simulator(strip(PixelMap.WATER));
        Course c = s.world().course();
        ShotResult r = east(s, c.start().x(), c.physics().maxSpeed());
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(20 * 0.25, r.endX(), 0.05); // where it entered
        Landing l = Landing.of(s.world(), r, c.start().x(), c.start().y());
        assertEquals(new Landing(c.start().x(), c.start().y(), 0, true), l);
    }

    @Test
    void acidSendsTheBallBackToTheCourseStart() throws Exception {
        Simulator s = simulator(strip(PixelMap.ACID));
        Course c = s.world().course();
        double from = 15 * 0.25;
        ShotResult r = east(s, from, c.physics().maxSpeed());
        assertEquals(Outcome.WATER, r.outcome());
        Landing l = Landing.of(s.world(), r, from, c.start().y());
        assertEquals(new Landing(c.start().x(), c.start().y(), 0, true), l);
    }

    /** Shallow water ends the stroke only where the ball comes to rest in it. */
    @Test
    void shallowWaterOnlyAtRest() throws Exception {
        Simulator s = simulator(strip(PixelMap.SHALLOW_WATER));
        Course c = s.world().course();
        ShotResult across = east(s, c.start().x(), 0.8 * c.physics().maxSpeed());
        assertEquals(Outcome.HOLED, across.outcome());
        // A weak shot from just before the strip stops in it.
        double from = 19 * 0.25;
        ShotResult in = east(s, from, 0.6);
        assertEquals(Outcome.WATER, in.outcome());
        assertTrue(in.endX() > 20 * 0.25 && in.endX() < 23 * 0.25, "ends at " + in.endX());
        Landing l = Landing.of(s.world(), in, from, c.start().y());
        assertEquals(new Landing(from, c.start().y(), 0, true), l);
        // Stopping short of it is a plain stop.
        ShotResult shortOf = east(s, 15 * 0.25, 0.3);
        assertEquals(Outcome.STOPPED, shortOf.outcome());
    }

    /**
     * Sticky walls keep the ball, bouncy ones (restitution 2) send it back further than blocks: how
     * far west the ball gets after meeting the strip (a bouncy wall sends it to the west fence).
     */
    @Test
    void wallKindsBounceDifferently() throws Exception {
        double[] back = new double[3];
        int[] elements = {PixelMap.STICKY, PixelMap.BLOCK, PixelMap.BOUNCY};
        for (int i = 0; i < 3; i++) {
            Simulator s = simulator(strip(elements[i]));
            Course c = s.world().course();
            double from = 15 * 0.25;
            double[] west = {Double.MAX_VALUE};
            boolean[] met = {false};
            ShotResult r = s.simulate(from, c.start().y(), 2.0, 0, (t, x, y, vx, vy) -> {
                met[0] |= vx < 0;
                if (met[0]) west[0] = Math.min(west[0], x);
            });
            assertEquals(Outcome.STOPPED, r.outcome());
            back[i] = 20 * 0.25 - west[0];
        }
        assertTrue(back[0] < back[1] && back[1] < back[2], java.util.Arrays.toString(back));
        assertFalse(back[0] > 0.3, "sticky: " + back[0]);
    }

    /**
     * A downhill field that pushes the ball back into a bouncy wall: the ball bounces, climbs
     * against the push, falls back and bounces again, losing speed each time, and comes to rest at
     * the wall. With bouncy walls above restitution 1 (as first imported) every bounce gave back the
     * fastest shot's speed and the ball bounced until the stroke's 10-minute limit (a sample track
     * did so on every shot).
     */
    @Test
    void aBallPushedIntoABouncyWallComesToRest() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 44, 12, TileMap.GRASS);
        Tracks.set(codes, 2, 22, TileMap.specialTile(1, PixelMap.GRASS)); // the hole out of the way
        for (int y = 1; y < 24; y++) {
            for (int x = 5; x <= 44; x++) Tracks.set(codes, x, y, TileMap.elementTile(0, PixelMap.DOWNHILL_N + 2, PixelMap.DOWNHILL_N + 2));
            Tracks.set(codes, 45, y, TileMap.elementTile(0, PixelMap.BOUNCY, PixelMap.BOUNCY));
        }
        Simulator s = simulator(codes);
        ShotResult r = east(s, s.world().course().start().x(), 1.0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertTrue(r.time() < 60, "came to rest after " + r.time() + " s");
        // At the wall: x = 45 tiles less the ball's radius.
        assertEquals(45 * 0.25 - s.world().course().physics().ballRadius(), r.endX(), 0.01);
    }
}
