package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;

/**
 * Long steps up to water and the bounds (docs/physics.md, "Step control"): a long step whose
 * stages meet them is tried again ending half a dt short of where its stages put the crossing, and
 * a step of dt then meets it, located inside that step as always.
 */
class LongStepShoreTest {
    /** h = c - s x: smooth, water beyond x = c / s. */
    private static Terrain slope(double c, double s) {
        return new Terrain() {
            public double height(double x, double y) {
                return c - s * x;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = c - s * x;
                out[1] = -s;
                out[2] = 0;
            }

            public boolean isSmooth() {
                return true;
            }
        };
    }

    @Test
    void aBallRollingIntoWaterEndsAtTheShoreAtTheClosedForm() {
        // Down a 2% slope (braking, mu_k 0.08) from x = -5 at 4 m/s into water beyond x = 5.
        double s = 0.02, muK = 0.08, v = 4;
        World world = TestWorlds.world(slope(0.1, s), muK, 0.2, 10);
        ShotResult r = TestWorlds.rk4(world).simulate(-5, 0, v, 0);
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(5, r.endX(), 1e-7);
        assertEquals(0, r.endY(), 1e-12);
        assertEquals(TestWorlds.timeToCover(10, v, TestWorlds.G * (muK - s)), r.time(), 1e-7);
        // 3.30 s in 26 steps (28 when steps of dt took the ball the last stretch to the shore).
        assertTrue(r.steps() <= 26, r.steps() + " steps");
    }

    @Test
    void aBallLeavingTheBoundsEndsOnThemAtTheClosedForm() {
        double s = 0.02, muK = 0.08, v = 4.5;
        World world = TestWorlds.world(slope(1, s), muK, 0.2, 10);
        ShotResult r = TestWorlds.rk4(world).simulate(-5, 0, v, 0);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(10, r.endX(), 1e-7);
        assertEquals(TestWorlds.timeToCover(15, v, TestWorlds.G * (muK - s)), r.time(), 1e-7);
        // 4.91 s in 38 steps (41 when steps of dt took it to the bounds).
        assertTrue(r.steps() <= 38, r.steps() + " steps");
    }
}
