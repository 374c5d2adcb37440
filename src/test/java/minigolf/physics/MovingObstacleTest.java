package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Moving obstacles (docs/course-format.md, "Moving obstacles"): kinematic, on the course clock. */
class MovingObstacleTest {
    // A bar 2 m long turning counter-clockwise about the origin once every 2 s.
    static final World BAR = ElementWorlds.flat("\"obstacles\": [{\"type\": \"box\", \"min\": [-1, -0.05, 0], \"max\": [1, 0.05, 0.2],"
            + " \"restitution\": 0.5, \"motion\": {\"type\": \"rotate\", \"pivot\": [0, 0, 0], \"period\": 2}}]");

    @Test
    void aTurningBarHitsAStillBallWhenItGetsThere() {
        // A ball put at (0.5, 0.3) (a 1 mm/s nudge: it stops at once) waits until the bar's face,
        // 0.05 m from its axis, comes within a ball radius of it: the bar has turned by the angle
        // of the ball's centre less asin((0.05 + r) / distance). The bar's face moves at
        // pi * distance there and the ball leaves at (1 + e) times that along the normal.
        double r = BAR.physics().ballRadius();
        ShotResult s = ElementWorlds.simulator(BAR).simulate(0.5, 0.3, 0.001, 0, 0, null);
        StrokeEvent hit = s.events().stream().filter(e -> e.type() == StrokeEvent.Type.COLLISION).findFirst().orElseThrow();
        double x = 0.5 + 0.001 * 0.001 / (2 * 0.981); // where the nudge left it
        double d = Math.hypot(x, 0.3);
        double angle = Math.atan2(0.3, x) - Math.asin((0.05 + r) / d);
        assertEquals(angle / Math.PI, hit.t(), 1e-6);
        double along = Math.sqrt(d * d - (0.05 + r) * (0.05 + r)); // the contact's distance along the bar
        assertEquals(1.5 * Math.PI * along, hit.speedAfter(), 1e-7);
    }

    @Test
    void theOutcomeDependsOnTheClockAndRepeatsWithThePeriod() {
        Simulator sim = ElementWorlds.simulator(BAR);
        ShotResult a = sim.simulateAt(0.0, -3, 0.02, 3, 0, 0);
        ShotResult b = sim.simulateAt(0.5, -3, 0.02, 3, 0, 0);
        ShotResult c = sim.simulateAt(2.0, -3, 0.02, 3, 0, 0);
        assertNotEquals(a.endX(), b.endX());
        assertEquals(a.endX(), c.endX(), 1e-9);
        assertEquals(a.endY(), c.endY(), 1e-9);
        // And it is deterministic.
        assertEquals(a, sim.simulateAt(0.0, -3, 0.02, 3, 0, 0));
    }

    @Test
    void aBallOutOfTheReachOfEveryMovingObstacleStops() {
        ShotResult r = ElementWorlds.simulator(BAR).simulate(-3, -3, 0.5, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-3 + 0.25 / (2 * 0.981), r.endX(), 2e-5);
    }

    @Test
    void aSlidingGatePushesTheBallAlong() {
        // A gate sliding +x at 1 m/s for 2 s, then back: a still ball in its way is knocked on.
        World slide = ElementWorlds.flat("\"obstacles\": [{\"type\": \"box\", \"min\": [-1, -0.5, 0], \"max\": [-0.9, 0.5, 0.3],"
                + " \"restitution\": 0, \"motion\": {\"type\": \"slide\", \"path\": [[0, 0, 0], [2, 0, 0]], \"period\": 4}}]");
        ShotResult r = ElementWorlds.simulator(slide).simulate(0, 0, 0.001, 0, 0, null);
        StrokeEvent hit = r.events().stream().filter(e -> e.type() == StrokeEvent.Type.COLLISION).findFirst().orElseThrow();
        double r0 = slide.physics().ballRadius();
        assertEquals(0.9 - r0 + 0.0005, hit.t(), 1e-3);
        // Restitution 0: it leaves with the gate's speed, and the least separation speed, enough to
        // get 1 mm ahead against its friction: sqrt(2 mu_k g 1 mm).
        assertEquals(1 + Math.sqrt(2 * 0.981 * 0.001), hit.speedAfter(), 1e-9);
        // Pushed along in millimetre hops while the gate moves on (2 m in 2 s), never crushed.
        assertEquals(Outcome.STOPPED, r.outcome());
        assertTrue(r.endX() > 1.0, "pushed along: " + r.endX());
    }
}
