package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The closed-form stop on a uniform slope shallower than mu_k ({@link PlaneStop}) against the
 * classic equations integrated here in steps of 1e-6 s, and the stopping tail that uses it
 * ({@link StoppingTail}) against the independent reference.
 */
class PlaneStopTest {
    private static final double G = 9.81;

    @Test
    void theClosedFormStopMatchesTheEquationsIntegratedInTinySteps() {
        double mu = 0.1;
        // Gradient (0.03, -0.04): s = 0.05, k = 2; and s = 0.09, k = 1.11 (a slow, long stop); headings
        // downhill, uphill, across, and in between.
        double[][] slopes = {{0.03, -0.04}, {0.09, 0}};
        double[][] velocities = {{-0.18, 0.24}, {0.3, -0.4}, {0.4, 0.3}, {-0.1, -0.45}, {0.2, 0.05}};
        PlaneStop p = new PlaneStop();
        for (double[] gr : slopes) {
            for (double[] v : velocities) {
                double[] fine = integrate(v[0], v[1], gr[0], gr[1], mu);
                p.solve(v[0], v[1], gr[0], gr[1], mu, G);
                String c = "slope " + gr[0] + "," + gr[1] + " v " + v[0] + "," + v[1];
                assertEquals(fine[0], p.dx, 2e-9, c);
                assertEquals(fine[1], p.dy, 2e-9, c);
                assertEquals(fine[2], p.time, 2e-6, c);
                assertEquals(fine[3], p.path, 2e-9, c);
            }
        }
    }

    @Test
    void onLevelGroundTheBallRunsStraightOnToItsBrakingDistance() {
        PlaneStop p = new PlaneStop();
        p.solve(0.3, -0.4, 0, 0, 0.1, G);
        double d = 0.25 / (2 * 0.1 * G);
        assertEquals(0.6 * d, p.dx, 1e-15);
        assertEquals(-0.8 * d, p.dy, 1e-15);
        assertEquals(0.5 / (0.1 * G), p.time, 1e-15);
        assertEquals(d, p.path, 1e-15);
    }

    @Test
    void aSlowBallRunningDownAPushZoneStopsInOneClosedFormPieceBesideAWall() {
        // Flat ground, a push of 0.9 m/s^2 along -y (0.0917 in slope units, just under mu_k 0.1), a
        // wall 0.2 m behind the ball, and the ball sent down the push at 0.3 m/s: it brakes at
        // g mu_k - 0.9 = 0.081 m/s^2 and stops 0.556 m on, in one closed-form piece. The tail's
        // reach was a square 1.25 v^2 / (2 g (mu_k - s)) = 0.69 m round the ball, which met the wall
        // and left the stop to 13 integrator steps; the ellipse round the path (its ends as foci,
        // 1.25 times its length) keeps clear of it.
        World w = ElementWorlds.flat("\"pushZones\": [{\"shape\": {\"type\": \"rect\", \"min\": [-5, -5], \"max\": [5, 5]},"
                + " \"push\": [0, -0.9]}], \"obstacles\": [{\"type\": \"wall\", \"from\": [-2, 0.4], \"to\": [2, 0.4],"
                + " \"thickness\": 0.05, \"height\": 0.1}]");
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0.2, 0, -0.3);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(0.2 - 0.09 / (2 * (0.1 * G - 0.9)), r.endY(), 1e-9);
        assertEquals(0, r.endX(), 1e-12);
        assertEquals(0.3 / (0.1 * G - 0.9), r.time(), 1e-9);
        assertEquals(1, r.steps());
    }

    @Test
    void aSlowBallOnAPlaneStopsWhereTheReferenceDoesInOneStepInsteadOfTheTailOfHalvedSteps() {
        // h = 0.1 + 0.03 x, mu_k 0.1: a putt across the slope at 1 m/s curls downhill and stops;
        // the integrator's steps near the stop were halved to dt/8 (37 steps in all, 7 now).
        World w = ElementWorlds.course("0.1 + 0.03*x", "");
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, 0.2, 1);
        minigolf.physics.reference.ReferenceResult ref = new minigolf.physics.reference.ReferenceSimulator(w).simulate(0, 0, 0.2, 1);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(ref.endX(), r.endX(), 1e-8);
        assertEquals(ref.endY(), r.endY(), 1e-8);
        assertTrue(r.steps() <= TAIL_STEPS, r.steps() + " steps");
    }

    /** Steps of the putt across the plane: the tail's closed form ends it in one. */
    private static final int TAIL_STEPS = 10;

    /**
     * The classic equations on the plane, RK4 in steps of 1e-5 s down to 1e-4 m/s (nearer the stop
     * its stages would flip friction), then the last 1e-4 m/s straight on at the deceleration there:
     * the displacement, the time and the path's length (the speed's trapezoids).
     */
    private static double[] integrate(double vx, double vy, double gx, double gy, double mu) {
        double x = 0, y = 0, t = 0, h = 1e-5, path = 0;
        while (true) {
            double v = Math.hypot(vx, vy);
            if (v < 1e-4) {
                double[] acc = a(vx, vy, gx, gy, mu);
                double deceleration = -(acc[0] * vx + acc[1] * vy) / v;
                double d = v / (2 * deceleration);
                return new double[] {x + vx * d, y + vy * d, t + v / deceleration, path + v * d};
            }
            double[] k1 = a(vx, vy, gx, gy, mu);
            double[] k2 = a(vx + h / 2 * k1[0], vy + h / 2 * k1[1], gx, gy, mu);
            double[] k3 = a(vx + h / 2 * k2[0], vy + h / 2 * k2[1], gx, gy, mu);
            double[] k4 = a(vx + h * k3[0], vy + h * k3[1], gx, gy, mu);
            x += h / 6 * (vx + 2 * (vx + h / 2 * k1[0]) + 2 * (vx + h / 2 * k2[0]) + vx + h * k3[0]);
            y += h / 6 * (vy + 2 * (vy + h / 2 * k1[1]) + 2 * (vy + h / 2 * k2[1]) + vy + h * k3[1]);
            vx += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
            vy += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
            path += h * 0.5 * (v + Math.hypot(vx, vy));
            t += h;
        }
    }

    private static double[] a(double vx, double vy, double gx, double gy, double mu) {
        double v = Math.hypot(vx, vy);
        return new double[] {-G * gx - mu * G * vx / v, -G * gy - mu * G * vy / v};
    }
}
