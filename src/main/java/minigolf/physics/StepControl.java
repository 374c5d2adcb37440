package minigolf.physics;

/**
 * Error control of the rolling RK4 step (docs/physics.md, "Step control"). The frame (dt, 1/60 s
 * in the game) stays the outer step: the game still sees the ball at every frame. Inside it a
 * rolling RK4 step is halved while its embedded error estimate ({@link RollingStep#errorEstimate})
 * is above {@link #TOLERANCE}, and the following steps keep the shorter length until the estimate
 * allows them to double again. On smooth ground at putting speeds the estimate stays below the
 * tolerance and nothing changes; across a grid's cell edges, on tight curves and on slow balls
 * whose friction turns with them it halves the step where the 1/60 s step loses millimetres.
 */
final class StepControl {
    /** Local position error (m) above which an RK4 step is halved. */
    static final double TOLERANCE = 5e-8;
    /** A step is halved at most this many times: sub-steps down to dt / 8. */
    static final int MAX_HALVINGS = 3;
    /**
     * Halving is given up where it divides the error estimate by less than 6 (16 on smooth
     * ground, 8 across a jump in curvature, 4 across a crease, where more halvings would not pay).
     */
    static final double KINK_RATIO = 1.0 / 6;
    /**
     * With the control, the slow step (semi-implicit and of first order: millimetres over a long,
     * slow roll on slopes near mu_k) takes over only below this fraction of the speed that gravity
     * and friction can change in a step; above it the controlled RK4 steps run.
     */
    static final double SLOW_FRACTION = 0.125;

    private final RollingStep rolling;
    private final double dt;
    private final double shortest;
    /** The step the last accepted one allows. */
    private double allowed;

    StepControl(RollingStep rolling, double dt) {
        this.rolling = rolling;
        this.dt = dt;
        this.shortest = dt / (1 << MAX_HALVINGS);
        this.allowed = dt;
    }

    /**
     * The length of the coming RK4 step, at most tau (tau split evenly where the allowed step is
     * shorter), halved while the error estimate is above the tolerance and halving pays. The
     * rolling step's start state must be set ({@link RollingStep#from}); on return its n* hold
     * the step of the returned length. An estimate 16 times below the tolerance lets the next
     * step double, up to dt.
     */
    double length(double tau, double a1x, double a1y) {
        double h = tau;
        if (allowed < tau) h = tau / Math.ceil(tau / allowed * (1 - 1e-12));
        double previous = Double.POSITIVE_INFINITY;
        while (true) {
            rolling.advance(h, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (!Double.isFinite(rolling.nx + rolling.ny + rolling.nvx + rolling.nvy)) return h;
            double error = rolling.errorEstimate();
            if (!(error > TOLERANCE) || h <= shortest || error > previous * KINK_RATIO) {
                allowed = error * 16 < TOLERANCE ? Math.min(dt, 2 * h) : h;
                return h;
            }
            previous = error;
            h = Math.max(shortest, 0.5 * h);
        }
    }
}
