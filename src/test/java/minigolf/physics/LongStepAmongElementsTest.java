package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.Magnet;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/**
 * Long steps among obstacles and push zones (docs/physics.md, "Step control"): a step may be long
 * wherever nothing reaches into the box round its own path, not only where nothing is within its
 * length all round, and inside a push zone that holds the whole box (the push is constant there).
 */
class LongStepAmongElementsTest {
    private static final double G = 9.81;
    /** Steps of the stripes shot: 67 when the control halved steps across each edge, 44 when the step after a cut restarted from its length, 35 now. */
    private static final int STRIPE_STEPS = 38;

    @Test
    void aBallRollingAlongAWallAFewCentimetresAwayTakesLongStepsAndStopsAtTheClosedForm() {
        // Flat, mu_k 0.1: from (-4, 0) at 2 m/s along x it stops after v^2 / (2 mu_k g) = 2.039 m
        // in 2.039 s, 0.08 m from a wall (its face at y = 0.1, less the ball's radius). A square
        // of a long step's length round the ball (8 dt at 2 m/s is 0.27 m) held the wall, so the
        // steps were at most 2 dt long (44 steps); the box round the path leaves it out (18).
        World w = ElementWorlds.flat("\"obstacles\": [{\"type\": \"wall\", \"from\": [-5, 0.14], \"to\": [5, 0.14],"
                + " \"thickness\": 0.08, \"height\": 0.1, \"restitution\": 0.7}]");
        ShotResult r = ElementWorlds.simulator(w).simulate(-4, 0, 2, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        double a = 0.1 * G;
        assertEquals(-4 + 4 / (2 * a), r.endX(), 1e-6);
        assertEquals(0, r.endY(), 1e-12);
        assertEquals(2 / a, r.time(), 1e-6);
        assertTrue(r.steps() <= 24, r.steps() + " steps");
    }

    @Test
    void aBallPushedAlongInsideAPushZoneTakesLongStepsAndStopsAtTheClosedForm() {
        // A push of 0.5 m/s^2 along the shot over the whole course: it decelerates at mu_k g - 0.5
        // and stops after v^2 / (2 (mu_k g - 0.5)) = 4.158 m; the pull (0.051) is below mu_s.
        // Before long steps were allowed inside a zone this took 251 steps of dt; now 41.
        World w = ElementWorlds.flat(String.format(PushZoneTest.EVERYWHERE, 0.5, 0));
        ShotResult r = ElementWorlds.simulator(w).simulate(-4, 0, 2, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        double a = 0.1 * G - 0.5;
        assertEquals(-4 + 4 / (2 * a), r.endX(), 1e-6);
        assertEquals(2 / a, r.time(), 1e-6);
        assertTrue(r.steps() <= 50, r.steps() + " steps");
    }

    @Test
    void theForceMayChangeOnlyWhereAZoneEdgeOrAMagnetReachesIn() {
        ForceField f = new ForceField(
                List.of(new PushZone(new Shape.Rect(new Vec2(0, 0), new Vec2(2, 1)), new Vec2(0.5, 0)),
                        new PushZone(new Shape.Circle(new Vec2(5, 0), 1), new Vec2(0, 0.5))),
                List.of(new Magnet(new Vec2(-3, 0), 0.5, 1)));
        assertFalse(f.mayChangeWithin(0.5, 0.2, 1.5, 0.8), "inside the rectangle");
        assertTrue(f.mayChangeWithin(1.5, 0.2, 2.5, 0.8), "across the rectangle's edge");
        assertFalse(f.mayChangeWithin(4.7, -0.3, 5.3, 0.3), "inside the circle");
        assertTrue(f.mayChangeWithin(5.5, 0.5, 5.9, 0.9), "a corner outside the circle");
        assertFalse(f.mayChangeWithin(2.5, -2, 3.5, -1.5), "clear of every zone");
        assertTrue(f.mayChangeWithin(-2.6, -0.1, -2.4, 0.1), "the magnet's reach");
    }

    @Test
    void aBallCrossingFrictionStripesIsCutAtEachEdgeWithoutHalvingTheStepsBeforeIt() {
        // Flat, mu_k 0.1 with three stripes of mu_k 0.15, each 0.5 m wide: from (-4, 0) at 3 m/s
        // along x it loses 2 g (0.1 d + 0.05 * 1.5) of v^2 and stops after d = 3.837 m, past them.
        // A step whose trial ends in another zone is cut at the edge (StepLocator.zoneEdge) at
        // once; before, the error control halved it first (the estimate sees the jump in friction).
        // The cut says nothing against the step's error: the next may be as long as the one before
        // (44 steps when it restarted from the cut's length, 35 now).
        String stripe = "{\"shape\": {\"type\": \"rect\", \"min\": [%s, -1], \"max\": [%s, 1]}, \"kineticFriction\": 0.15, \"staticFriction\": 0.3}";
        World w = ElementWorlds.flat("\"zones\": [" + String.format(stripe, -3, -2.5) + ", " + String.format(stripe, -2, -1.5)
                + ", " + String.format(stripe, -1, -0.5) + "]");
        ShotResult r = ElementWorlds.simulator(w).simulate(-4, 0, 3, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        double d = (9 / (2 * G) - 0.05 * 1.5) / 0.1;
        assertEquals(-4 + d, r.endX(), 1e-6);
        assertEquals(0, r.endY(), 1e-12);
        assertTrue(r.steps() <= STRIPE_STEPS, r.steps() + " steps");
    }
}
