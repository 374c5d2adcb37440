package minigolf.physics;

/**
 * Error control of the rolling step (docs/physics.md, "Step control"). Steps follow their own
 * lengths, not the frames ({@link FrameView} shows the ball at frame times). A step of at most dt
 * (1/60 s in the game) is RK4's: halved while its embedded error estimate
 * ({@link RollingStep#errorEstimate}) is above {@link #TOLERANCE}, which happens across a grid's
 * cell edges, on tight curves and on slow balls whose friction turns with them. Where the estimate
 * allows, the next step doubles: beyond dt, up to {@link #MAX_GROWTH} dt, it is a long step of the
 * fifth-order Dormand-Prince formula ({@link RollingStep#advanceLong}), held to
 * {@link #LONG_TOLERANCE} per dt, and only where {@link RollingPhase} finds nothing within its
 * reach that needs the step's own length.
 */
final class StepControl {
    /** Local position error (m) above which an RK4 step is halved. */
    static final double TOLERANCE = 5e-8;
    /**
     * A step longer than dt (a long step: the fifth-order Dormand-Prince formula, where nothing is
     * within its reach) is held to this error estimate per dt of its length (m). Its estimate, the
     * fifth- minus the fourth-order solution, overstates the step's own error about a hundredfold
     * on smooth ground (docs/physics.md, "Step control").
     */
    static final double LONG_TOLERANCE = 4e-9;
    /**
     * The next long step is chosen so that its estimate would be this fraction of the tolerance
     * (a rejected long step costs its seven stages and holds the next {@link #PAUSE} steps to dt).
     */
    static final double LONG_SAFETY = 0.5;
    /** After a long step is rejected, this many steps of at most dt pass before one may be long again. */
    static final int PAUSE = 4;
    /** A step is halved at most this many times: sub-steps down to dt / 8. */
    static final int MAX_HALVINGS = 3;
    /**
     * A step may double up to this many times dt where the estimate allows it and nothing is
     * within its reach ({@link RollingPhase}: obstacles, the hole, a turn or a stop, water).
     */
    static final int MAX_GROWTH = 8;
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
    /**
     * With the control, the analytic stop looks this fraction of dt ahead, and a slow step is that
     * long, whatever the step the control has chosen.
     */
    static final double STOP_AHEAD = 0.25;

    private final RollingStep rolling;
    /** Where friction or push zones have edges, the locator that tells a step that crosses one (null: none). */
    StepLocator edges;
    private final double dt;
    private final double shortest;
    private final double longest;
    /** The step the last accepted one allows. */
    private double allowed;
    /** Steps left before a step may be long again ({@link #PAUSE}). */
    private int pause;

    StepControl(RollingStep rolling, double dt) {
        this.rolling = rolling;
        this.dt = dt;
        this.shortest = dt / (1 << MAX_HALVINGS);
        this.longest = dt * MAX_GROWTH;
        this.allowed = dt;
    }

    /** The length the last accepted step allows the next one. */
    double allowed() {
        return allowed;
    }

    /**
     * The length after an accepted long step of length h with this error estimate: the length at
     * which the estimate (growing like h^5 against a tolerance growing like h) would reach
     * {@link #LONG_SAFETY} of the tolerance, at most twice h and {@link #MAX_GROWTH} dt, at least dt.
     */
    private double nextLong(double h, double error) {
        double room = LONG_SAFETY * LONG_TOLERANCE * h / dt / error;
        double factor = room >= 16 ? 2 : Math.sqrt(Math.sqrt(room));
        return Math.max(dt, Math.min(longest, h * factor));
    }

    /** Allows the next step at most {@code length} (a long step that something inside it vetoed). */
    void limit(double length) {
        allowed = Math.min(allowed, length);
    }

    /** Whether a step of this length is longer than dt: it must keep clear of what is within its reach. */
    boolean isLong(double length) {
        return length > dt * (1 + 1e-9);
    }

    /** A new stroke: the first step may be as long as any (it is halved where it must). */
    void reset() {
        allowed = longest;
        pause = 0;
    }

    /**
     * The length of the coming step, at most tau (tau split evenly where the allowed step is
     * shorter). A step up to dt is RK4's, halved while its error estimate is above
     * {@link #TOLERANCE} and halving pays; a longer one is the fifth-order step's
     * ({@link RollingStep#advanceLong}), halved while its estimate is above
     * {@link #LONG_TOLERANCE} per dt. The rolling step's start state must be set
     * ({@link RollingStep#from}); on return its n* hold the step of the returned length. An
     * estimate that promises the tolerance at twice the length lets the next step double.
     */
    double length(double tau, double a1x, double a1y) {
        double h = tau;
        if (allowed < tau) h = tau / Math.ceil(tau / allowed * (1 - 1e-12));
        double start = allowed;
        double previous = Double.POSITIVE_INFINITY;
        boolean longRejected = false;
        while (true) {
            rolling.advance(h, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (!Double.isFinite(rolling.nx + rolling.ny + rolling.nvx + rolling.nvy)) return h;
            double doubled = Math.min(longest, 2 * h);
            if (isLong(h)) {
                double error = rolling.longErrorEstimate();
                if (!(error > LONG_TOLERANCE * h / dt)) {
                    // The fifth- minus fourth-order estimate grows as h^5, its tolerance as h: the
                    // next step is the length that would meet it with a margin, up to twice this one.
                    double next = nextLong(h, error);
                    allowed = longRejected ? Math.min(h, next) : h < start ? Math.max(next, start) : next;
                    return h;
                }
                longRejected = true;
                pause = PAUSE;
                h *= 0.5;
                continue;
            }
            if (edges != null && previous == Double.POSITIVE_INFINITY && edges.leavesRegion(rolling.nx, rolling.ny)) {
                // Across a zone's edge the estimate sees the jump, not the step's error: the step
                // is cut at the edge (StepLocator.zoneEdge), with the start's friction and push;
                // it says nothing against the length allowed before.
                allowed = Math.max(h, start);
                if (pause > 0) pause--;
                return h;
            }
            double error = rolling.errorEstimate();
            if (!(error > TOLERANCE) || h <= shortest || error > previous * KINK_RATIO) {
                // A step the caller cut short (the rest of a step after a contact) says nothing
                // against the length allowed before; one halved here keeps its length for now,
                // and a long step rejected holds the next ones to dt for a while.
                boolean grow = previous == Double.POSITIVE_INFINITY && !longRejected && error * 16 < TOLERANCE
                        && (pause == 0 || !isLong(doubled));
                allowed = grow ? Math.max(doubled, start) : h;
                if (pause > 0) pause--;
                return h;
            }
            previous = error;
            h = Math.max(shortest, 0.5 * h);
        }
    }
}
