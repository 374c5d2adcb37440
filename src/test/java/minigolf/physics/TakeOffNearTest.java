package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import minigolf.terrain.ExpressionTerrain;
import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;

/**
 * A long step is refused where the ground curves away near take-off (TakeOff.near, one terrain
 * height at the straight step's end). Where its own stages saw the ground bend away by less than
 * half of that measure (TakeOff.gentleAlong, RollingStep.stageBend) the height is not asked, nor
 * by the take-off check of a step of any length on smooth ground whose stages saw it bend away by
 * less than half of the measure from which TakeOff.takesOff looks further (TakeOff.staysDown).
 */
class TakeOffNearTest {
    private static final double DT = 1.0 / 60;

    /** Heights asked of the terrain (full samples are not counted). */
    private int heights;

    @Test
    void gentleStagesNeverHideGroundThatNearOrTakesOffLooksAt() {
        // Bumps whose curvature v^T H v reaches -g/4 (near's measure) at a few metres per second.
        Terrain bumps = new ExpressionTerrain("0.3*sin(2*x)*cos(1.5*y) + 0.05*x");
        World world = TestWorlds.world(bumps, 0.08, 0.2, 20);
        RollingStep step = new RollingStep(bumps, world.friction(), null, TestWorlds.G, false, Integrator.RK4, DT);
        TakeOff takeOff = new TakeOff(bumps, step, TestWorlds.G);
        SplittableRandom random = new SplittableRandom(5);
        double[] ground = new double[3];
        int gentle = 0, near = 0, stays = 0, steep = 0;
        for (int i = 0; i < 40_000; i++) {
            double x = random.nextDouble(-5, 5), y = random.nextDouble(-5, 5);
            double angle = random.nextDouble(2 * Math.PI), speed = random.nextDouble(0.3, 5);
            double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
            // Half the steps of RK4 (up to dt), half long steps (Dormand-Prince, up to 8 dt).
            double tau = DT * (i % 2 == 0 ? random.nextDouble(0.1, 1) : random.nextDouble(1.5, 8));
            bumps.sample(x, y, ground);
            step.reset();
            step.acceleration(ground[1], ground[2], 0, 0, 0.08, vx, vy);
            step.from(x, y, vx, vy, ground[1], ground[2], 0.08, 0, 0);
            step.advance(tau, RollingStep.Kind.INTEGRATOR, step.ax, step.ay);
            boolean isGentle = takeOff.gentleAlong(step.stageBend, tau);
            if (takeOff.staysDown(step.stageBend, tau)) stays++;
            assertFalse(takeOff.staysDown(step.stageBend, tau) && departure(bumps, x, y, vx, vy, ground, tau) >= 0.25 * TestWorlds.G * tau * tau,
                    "step " + i + " stays down");
            boolean isNear = takeOff.near(x, y, vx, vy, ground[0], ground[1], ground[2], tau);
            assertFalse(isGentle && isNear, "step " + i + " at (" + x + ", " + y + "), v (" + vx + ", " + vy + "), tau " + tau);
            if (isGentle) gentle++;
            if (isNear) near++;
            if (departure(bumps, x, y, vx, vy, ground, tau) >= 0.25 * TestWorlds.G * tau * tau) steep++;
        }
        // Both kinds occur, so the check above has something to refuse.
        assertTrue(gentle > 5_000 && near > 1_000 && stays > 10_000 && steep > 1_000,
                "gentle " + gentle + ", near " + near + ", stays down " + stays + ", takesOff looks further " + steep);
    }

    /** How far the ground at the straight step's end lies below the start's tangent plane (TakeOff's measure). */
    private static double departure(Terrain terrain, double x, double y, double vx, double vy, double[] start, double tau) {
        return start[0] + (start[1] * vx + start[2] * vy) * tau - terrain.height(x + vx * tau, y + vy * tau);
    }

    @Test
    void aLongRollOverGentleGroundAsksNoHeightsForItsTakeOffChecks() {
        // Across the lake's bowl (h = 0.4 (0.9 - exp(-(x^2 + y^2) / 8)), water within 0.92 m of the
        // centre) and up its far side, where the ball stops: every step but the last few is long.
        Terrain counted = TestWorlds.countingHeights(TestWorlds.lake(), () -> heights++);
        Simulator simulator = TestWorlds.rk4(TestWorlds.world(counted, 0.08, 0.2, 5));
        heights = 0;
        ShotResult r = simulator.simulate(-3, -1.5, 3.5, 0.4);
        assertEquals(Outcome.STOPPED, r.outcome(), r.toString());
        // No height in its 56 steps; 55 when each step's take-off check asked one.
        assertEquals(0, heights, "heights in " + r.steps() + " steps");
    }
}
