package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * The stopping tail (docs/physics.md, "The stopping tail"): a slow ball on ground shallower than
 * mu_k, with nothing within its reach, rolls to its stop in one closed-form piece
 * ({@link PlaneStop}) instead of the integrator's steps, which the heading's turn towards the fall
 * line near the stop (like (t_stop - t)^(1/(k-1))) holds down to dt/8 for the last tenth of a
 * metre per second. The ground is taken as the plane with the ground's gradient at the midpoint of
 * the chord to the stop, found by fixed-point iteration from the start's tangent plane: on
 * quadratic ground the height difference between the ends, which decides how far friction has to
 * brake the ball, is exactly that gradient times the chord. The piece is taken only where the
 * error estimate is below {@link #TOLERANCE}: the iteration's last change plus the tail's length
 * times the change of the pull gradient between its ends over the margin mu_k - s (first order:
 * on `chip-wall` a tail of 0.09 m across a change of 7e-6 ended 6 um from the reference).
 */
final class StoppingTail {
    /** Balls faster than this (m/s) are left to the integrator. */
    static final double MAX_SPEED = 0.5;
    /** The error estimate (m) below which the closed form is taken (chosen on seed-2 shots, not bench-accuracy's). */
    static final double TOLERANCE = 1e-6;
    /** Fixed-point iterations of the chord's midpoint. */
    static final int ITERATIONS = 2;
    /**
     * After a tail is refused at some speed, it is tried again only below this fraction of it, or
     * below the speed at which its estimate (growing like the speed^4: the length squared) would pass.
     */
    static final double RETRY = 0.8;
    /** How much further than its bound from the sampled slopes the path may reach (the slope between samples). */
    static final double REACH_FACTOR = 1.25;

    /** Whether anything that needs the integrator's steps reaches into a rectangle of centre positions. */
    interface Reach {
        boolean near(double minX, double minY, double maxX, double maxY);
    }

    private final BallState ball;
    private final GroundCache ground;
    private final Terrain terrain;
    private final StepLocator locate;
    private final StrokeReports reports;
    private final RestRule rest;
    private final double gravity;
    private final double dt;
    private final double maxTime;
    private final PlaneStop plane = new PlaneStop();
    private final double[] sample = new double[3];
    private final double[] pull = new double[2];
    /** Set by the rolling phase: its obstacles, zones' edges, magnets, teleports and (capture rule) hole. */
    Reach reach;
    /** The speed at which the tail was last tried this stroke, and the speed below which it is tried again. */
    private double lastTried = Double.POSITIVE_INFINITY, retryBelow = Double.POSITIVE_INFINITY;

    StoppingTail(BallState ball, GroundCache ground, Terrain terrain, StepLocator locate, StrokeReports reports,
                 RestRule rest, double gravity, double dt, double maxTime) {
        this.ball = ball;
        this.ground = ground;
        this.terrain = terrain;
        this.locate = locate;
        this.reports = reports;
        this.rest = rest;
        this.gravity = gravity;
        this.dt = dt;
        this.maxTime = maxTime;
    }

    /** A new stroke. */
    void reset() {
        lastTried = Double.POSITIVE_INFINITY;
        retryBelow = Double.POSITIVE_INFINITY;
    }

    /**
     * Rolls the ball (speed &gt; 0 on ground whose pull gradient is shallower than its mu_k, not
     * leaning) to its stop in one piece and returns true, or returns false and leaves it as it is.
     */
    boolean stops(double speed) {
        // Tried again only once the ball is much slower (or faster: it gained speed since).
        if (!(speed <= MAX_SPEED) || (speed > retryBelow && speed <= lastTried)) return false;
        lastTried = speed;
        retryBelow = RETRY * speed;
        BallState b = ball;
        double mu = b.muK;
        double s0 = norm(b.pullX, b.pullY);
        plane.solve(b.vx, b.vy, b.pullX, b.pullY, mu, gravity);
        double dx = plane.dx, dy = plane.dy;
        double steepest = s0, lowest = b.h, change = Double.POSITIVE_INFINITY;
        for (int i = 0; i < ITERATIONS; i++) {
            terrain.sample(b.x + 0.5 * dx, b.y + 0.5 * dy, sample);
            pullAt(sample);
            double s = norm(pull[0], pull[1]);
            if (!(s < mu)) return false;
            steepest = Math.max(steepest, s);
            lowest = Math.min(lowest, sample[0]);
            plane.solve(b.vx, b.vy, pull[0], pull[1], mu, gravity);
            change = norm(plane.dx - dx, plane.dy - dy);
            dx = plane.dx;
            dy = plane.dy;
        }
        double ex = b.x + dx, ey = b.y + dy, time = plane.time;
        if (!(b.t + time < maxTime)) return false;
        double[] end = ground.at(ex, ey);
        pullAt(end);
        double sEnd = norm(pull[0], pull[1]);
        if (!(sEnd < mu)) return false;
        steepest = Math.max(steepest, sEnd);
        lowest = Math.min(lowest, end[0]);
        // First order in the slope's change over the tail: the end moves by about the tail's length
        // times that change over the margin of friction (the midpoint's plane does not cancel it).
        double spread = norm(pull[0] - b.pullX, pull[1] - b.pullY) / (mu - steepest);
        double length = norm(dx, dy);
        double estimate = change + length * spread;
        if (!(estimate <= TOLERANCE)) {
            retryBelow = Math.min(retryBelow, speed * Math.sqrt(Math.sqrt(TOLERANCE / estimate)));
            return false;
        }
        // Braking at least g (mu_k - steepest), the ball's path is no longer than this.
        double r = REACH_FACTOR * speed * speed / (2 * gravity * (mu - steepest)) + RollingPhase.PATH_MARGIN;
        // Nor, with the same margins, than the plane's path to its end: it stays inside the ellipse
        // with the start and the end as foci and that length as its string, whose box is far
        // tighter where the ball heads down the fall line (on a push zone with mu_k - s small, r
        // reaches metres). The reach is the box of both.
        double string = REACH_FACTOR * plane.path + RollingPhase.PATH_MARGIN + estimate;
        double semi = 0.5 * string, focal = 0.5 * length;
        double minor = Math.max(0, semi * semi - focal * focal);
        double ux = length > 0 ? dx / length : 0, uy = length > 0 ? dy / length : 0;
        double halfX = Math.sqrt(minor + focal * focal * ux * ux), halfY = Math.sqrt(minor + focal * focal * uy * uy);
        double minX = Math.max(b.x - r, b.x + 0.5 * dx - halfX), maxX = Math.min(b.x + r, b.x + 0.5 * dx + halfX);
        double minY = Math.max(b.y - r, b.y + 0.5 * dy - halfY), maxY = Math.min(b.y + r, b.y + 0.5 * dy + halfY);
        if (!locate.inPlay(minX, minY) || !locate.inPlay(maxX, maxY) || reach.near(minX, minY, maxX, maxY)) return false;
        // Water: the path keeps above the lowest sample by more than the slope can drop it.
        if (lowest - steepest * r <= 0 || locate.hazardAtEnd(ex, ey) != null) return false;
        b.markStepStart();
        b.x = ex;
        b.y = ey;
        b.vx = 0;
        b.vy = 0;
        b.t += time;
        b.steps++;
        b.pieceTime = time;
        if (time > dt * (1 + 1e-9)) reports.path(b.px, b.py, b.pvx, b.pvy, b.pt, b.x, b.y, 0, 0, b.t);
        b.sampleGround();
        b.z = b.h;
        rest.forget();
        reports.state();
        return true;
    }

    /** |(x, y)|: Math.hypot's care for overflow costs more than the rest of a try here (slopes and metres). */
    private static double norm(double x, double y) {
        return Math.sqrt(x * x + y * y);
    }

    /** The pull gradient (the ground's, tilted by the start's push: constant where nothing reaches in) of a ground sample. */
    private void pullAt(double[] ground) {
        BallState b = ball;
        if (b.fx == 0 && b.fy == 0) {
            pull[0] = ground[1];
            pull[1] = ground[2];
        } else {
            ForceField.pullGradient(ground[1], ground[2], b.fx, b.fy, gravity, false, pull);
        }
    }
}
