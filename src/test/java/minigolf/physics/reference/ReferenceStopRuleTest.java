package minigolf.physics.reference;

import static minigolf.physics.reference.ReferenceWorlds.G;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.physics.Outcome;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Rule 1 of "Coming to rest" on the plane h = 0.15x (μk 0.1, μs 0.2), where a ball rolling uphill
 * turns round at a minimum of its speed, against the closed form of docs/physics.md:
 * V_min = V·(T*^(k−1) + T*^(k+1)) / (T^(k−1) + T^(k+1)), T = tan(ψ/2), T*² = (1 − k)/(1 + k).
 */
class ReferenceStopRuleTest {
    private static final double S = 0.15, MU_K = 0.1, K = MU_K / S;
    private final World plane = ReferenceWorlds.world(ReferenceWorlds.plane(S, 4), MU_K, 0.2, 20);

    /** The minimum speed still ahead of a ball at speed v heading psi from straight downhill. */
    static double minimumSpeed(double v, double psi, double k) {
        double t = Math.tan(psi / 2), tStar = Math.sqrt((1 - k) / (1 + k));
        return v * (Math.pow(tStar, k - 1) + Math.pow(tStar, k + 1)) / (Math.pow(t, k - 1) + Math.pow(t, k + 1));
    }

    /** The uphill shot at speed v whose minimum speed is vMin: its angle off straight up, by bisection. */
    static double angleOffUphillFor(double v, double vMin) {
        double lo = 1e-9, hi = 1;
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            if (minimumSpeed(v, Math.PI - mid, K) < vMin) lo = mid; else hi = mid;
        }
        return 0.5 * (lo + hi);
    }

    private ReferenceResult shoot(double vx, double vy) {
        ReferenceResult r = new ReferenceSimulator(plane).simulate(-10, 0, vx, vy);
        assertTrue(r.covered(), r.note());
        return r;
    }

    @Test
    void theDocumentedExampleHasAMinimumOf21MillimetresPerSecond() {
        double psi = Math.PI - Math.atan2(0.2, 2);
        assertEquals(0.0213, minimumSpeed(Math.hypot(2, 0.2), psi, K), 0.0005);
    }

    @Test
    void straightUpStopsAtTheOneDimensionalDistanceAndNearlyStraightUpStopsBesideIt() {
        ReferenceResult up = shoot(2, 0);
        assertEquals(Outcome.STOPPED, up.outcome());
        assertEquals(-10 + 4 / (2 * G * (S + MU_K)), up.endX(), 1e-8);
        ReferenceResult nano = shoot(2, 1e-9);
        assertEquals(Outcome.STOPPED, nano.outcome());
        assertEquals(up.endX(), nano.endX(), 1e-8);
        assertEquals(0, nano.endY(), 1e-8);
        ReferenceResult off = shoot(2, 0.02);
        assertEquals(Outcome.STOPPED, off.outcome());
        assertEquals(up.endX(), off.endX(), 0.01);
    }

    @Test
    void aMinimumAboveOneMillimetrePerSecondTurnsRoundAndRollsDownAndOut() {
        ReferenceResult r = shoot(2, 0.2);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(-20, r.endX(), 1e-9);
    }

    @Test
    void theSplitLiesWhereTheClosedFormMinimumIsOneMillimetrePerSecond() {
        double v = 2;
        double below = angleOffUphillFor(v, 0.95e-3), above = angleOffUphillFor(v, 1.05e-3);
        ReferenceResult stops = shoot(v * Math.cos(below), v * Math.sin(below));
        ReferenceResult turns = shoot(v * Math.cos(above), v * Math.sin(above));
        assertEquals(Outcome.STOPPED, stops.outcome());
        assertEquals(Outcome.OUT, turns.outcome());
        // The ball that stops does so at its speed minimum, near the straight shot's rest point.
        assertEquals(-10 + v * v / (2 * G * (S + MU_K)), stops.endX(), 0.005);
    }
}
