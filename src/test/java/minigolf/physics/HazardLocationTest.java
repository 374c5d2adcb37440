package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;

/**
 * Water and the bounds are located inside a step on the step's cubic by false position on the
 * clearance (height above the water, depth inside the bounds), then confirmed by trial steps
 * (docs/physics.md, "Water and the bounds"): the crossing as exact as bisection made it, for a
 * few terrain heights instead of 27.
 */
class HazardLocationTest {
    /** Heights asked of the terrain (full samples are not counted). */
    private int heights;

    /** The plane h = c - s x + cross y (TestWorlds.plane), smooth (long steps allowed), counting heights. */
    private Terrain slope(double c, double s, double cross) {
        return TestWorlds.countingHeights(TestWorlds.plane(-s, cross, c), () -> heights++);
    }

    @Test
    void aBallRollingIntoWaterIsLocatedAtTheShoreWithFewHeights() {
        // Down a 2% slope (braking, mu_k 0.08) from x = -5 at 4 m/s into water beyond x = 5.
        double s = 0.02, muK = 0.08, v = 4;
        World world = TestWorlds.world(slope(0.1, s, 0), muK, 0.2, 10);
        Simulator simulator = TestWorlds.rk4(world);
        heights = 0;
        ShotResult r = simulator.simulate(-5, 0, v, 0);
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(5, r.endX(), 1e-7);
        assertEquals(TestWorlds.timeToCover(10, v, TestWorlds.G * (muK - s)), r.time(), 1e-7);
        // 9 heights in the whole shot (35 while every step's take-off check asked one, TakeOffNearTest);
        // bisection on the cubic asked 27 to locate the shore (57 in all).
        assertTrue(heights <= 12, "water heights " + heights);
    }

    @Test
    void aBallLeavingTheBoundsAtAnAngleIsLocatedOnThemWithFewHeights() {
        // Up a gentle cross slope, diagonally out through x = 10 (the bounds are +-10).
        double muK = 0.08;
        World world = TestWorlds.world(slope(1, 0.01, 0.005), muK, 0.2, 10);
        Simulator simulator = TestWorlds.rk4(world);
        heights = 0;
        ShotResult r = simulator.simulate(0, 0, 4.5, 1.2);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(10, r.endX(), 1e-7);
        assertTrue(Math.abs(r.endY()) < 10, "leaves through x = 10, at y = " + r.endY());
        // 3 heights in the whole shot (25 while every step's take-off check asked one); bisection asked
        // one for each of its 27 points inside the bounds (33 in all).
        assertTrue(heights <= 6, "out heights " + heights);
    }
}
