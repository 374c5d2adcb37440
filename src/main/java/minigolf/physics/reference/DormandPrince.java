package minigolf.physics.reference;

/**
 * The Dormand–Prince 5(4) embedded Runge–Kutta pair (Dormand & Prince 1980; the coefficients and
 * the 4th-order dense output as in Hairer, Nørsett & Wanner, "Solving ODEs I", code DOPRI5), with
 * its own step-size control. Written for the reference only: it shares nothing with the engine's
 * fixed-step integrators.
 *
 * <p>Use: {@link #attempt} one step of size h from (t, y); if it returns true the step is accepted,
 * {@link #interpolate} gives the state anywhere inside it and {@link #accept} moves on to its end.
 * Not thread-safe (scratch arrays), one per simulator.
 */
final class DormandPrince {
    /** The right-hand side y' = f(y) (the rolling equations do not depend on t). */
    interface Rhs {
        void derivative(double[] y, double[] dydt);
    }

    private static final double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9;
    private static final double A21 = 1.0 / 5;
    private static final double A31 = 3.0 / 40, A32 = 9.0 / 40;
    private static final double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
    private static final double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729;
    private static final double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176,
            A65 = -5103.0 / 18656;
    private static final double A71 = 35.0 / 384, A73 = 500.0 / 1113, A74 = 125.0 / 192, A75 = -2187.0 / 6784,
            A76 = 11.0 / 84;
    /** The 5th-order solution minus the embedded 4th-order one. */
    private static final double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200,
            E6 = 22.0 / 525, E7 = -1.0 / 40;
    private static final double D1 = -12715105075.0 / 11282082432.0, D3 = 87487479700.0 / 32700410799.0,
            D4 = -10690763975.0 / 1880347072.0, D5 = 701980252875.0 / 199316789632.0,
            D6 = -1453857185.0 / 822651844.0, D7 = 69997945.0 / 29380423.0;

    private final int n;
    private final double[] tolerance;
    private final double[] k1, k2, k3, k4, k5, k6, k7, stage, next;
    private final double[] r1, r2, r3, r4, r5;
    private double t0, h;
    private boolean fresh = true;

    /** @param tolerance the absolute error allowed per step in each component */
    DormandPrince(double[] tolerance) {
        this.n = tolerance.length;
        this.tolerance = tolerance.clone();
        k1 = new double[n]; k2 = new double[n]; k3 = new double[n]; k4 = new double[n];
        k5 = new double[n]; k6 = new double[n]; k7 = new double[n]; stage = new double[n]; next = new double[n];
        r1 = new double[n]; r2 = new double[n]; r3 = new double[n]; r4 = new double[n]; r5 = new double[n];
    }

    /** Forgets the derivative carried over from the last step (the state was changed from outside). */
    void restart() {
        fresh = true;
    }

    /**
     * Tries a step of size h from (t, y). Returns the error ratio (≤ 1: accepted, the step's end is
     * then in {@link #end()}); a ratio above 1 rejects the step and nothing changes but the scratch.
     */
    double attempt(Rhs f, double t, double[] y, double step) {
        if (fresh) {
            f.derivative(y, k1);
            fresh = false;
        }
        for (int i = 0; i < n; i++) stage[i] = y[i] + step * A21 * k1[i];
        f.derivative(stage, k2);
        for (int i = 0; i < n; i++) stage[i] = y[i] + step * (A31 * k1[i] + A32 * k2[i]);
        f.derivative(stage, k3);
        for (int i = 0; i < n; i++) stage[i] = y[i] + step * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        f.derivative(stage, k4);
        for (int i = 0; i < n; i++) stage[i] = y[i] + step * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        f.derivative(stage, k5);
        for (int i = 0; i < n; i++) {
            stage[i] = y[i] + step * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        }
        f.derivative(stage, k6);
        for (int i = 0; i < n; i++) {
            next[i] = y[i] + step * (A71 * k1[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i]);
        }
        f.derivative(next, k7);
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double e = step * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            double ratio = e / tolerance[i];
            sum += ratio * ratio;
        }
        double err = Math.sqrt(sum / n);
        if (!(err <= 1)) return Double.isNaN(err) ? Double.POSITIVE_INFINITY : err;
        t0 = t;
        h = step;
        for (int i = 0; i < n; i++) {
            double diff = next[i] - y[i];
            double bspl = step * k1[i] - diff;
            r1[i] = y[i];
            r2[i] = diff;
            r3[i] = bspl;
            r4[i] = diff - step * k7[i] - bspl;
            r5[i] = step * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
        return err;
    }

    /** The next step size after a step with this error ratio (the usual safety factor 0.9, growth within [0.2, 5]). */
    static double nextStep(double step, double err) {
        double factor = err == 0 ? 5 : 0.9 * Math.pow(err, -0.2);
        return step * Math.max(0.2, Math.min(5, factor));
    }

    /** The accepted step's end state. */
    double[] end() {
        return next;
    }

    double stepStart() {
        return t0;
    }

    double stepEnd() {
        return t0 + h;
    }

    /** The dense output at time t within the last accepted step (4th order, continuous). */
    void interpolate(double t, double[] out) {
        double theta = (t - t0) / h, theta1 = 1 - theta;
        for (int i = 0; i < n; i++) {
            out[i] = r1[i] + theta * (r2[i] + theta1 * (r3[i] + theta * (r4[i] + theta1 * r5[i])));
        }
    }

    /** Moves on to the accepted step's end: its derivative becomes the next step's first stage (FSAL). */
    void accept(double[] y) {
        System.arraycopy(next, 0, y, 0, n);
        System.arraycopy(k7, 0, k1, 0, n);
    }
}
