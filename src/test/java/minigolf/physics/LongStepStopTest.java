package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;

/**
 * Long steps on ground shallower than mu_k come up to the stop (docs/physics.md, "Step control"):
 * there the ball cannot turn, so the rest rule's turn horizon does not hold them back.
 */
class LongStepStopTest {
    /** h = 1 - s x, smooth (long steps allowed), dry within the tests' bounds. */
    private static Terrain smoothSlope(double s) {
        return new Terrain() {
            public double height(double x, double y) {
                return 1 - s * x;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = 1 - s * x;
                out[1] = -s;
                out[2] = 0;
            }

            public boolean isSmooth() {
                return true;
            }
        };
    }

    @Test
    void aBallBrakingDownAShallowSlopeStopsAtTheClosedFormInFewSteps() {
        double s = 0.03, muK = 0.1, v = 3;
        World world = TestWorlds.world(smoothSlope(s), muK, 0.2, 10);
        ShotResult r = TestWorlds.rk4(world).simulate(-5, 0, v, 0);
        double deceleration = TestWorlds.G * (muK - s);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-5 + v * v / (2 * deceleration), r.endX(), 1e-6);
        assertEquals(0, r.endY(), 1e-12);
        assertEquals(v / deceleration, r.time(), 1e-6);
        // 4.37 s: 33 steps of 8 dt, then a few up to the stop (45 when the last 0.15 s took steps of dt).
        assertTrue(r.steps() <= 38, r.steps() + " steps");
    }

    @Test
    void aBallRollingUpASlopeSteeperThanMuKKeepsItsTurnHorizon() {
        // Up a slope of 0.15 > mu_k: it turns, and the rule decides 1/15 s before the turn, in
        // steps of at most dt: the stop (straight up the fall line) is at the closed form.
        double s = 0.15, muK = 0.1, v = 2;
        World world = TestWorlds.world(smoothSlope(-s), muK, 0.2, 10);
        ShotResult r = TestWorlds.rk4(world).simulate(-5, 0, v, 0);
        double deceleration = TestWorlds.G * (muK + s);
        assertEquals(-5 + v * v / (2 * deceleration), r.endX(), 1e-6);
    }
}
