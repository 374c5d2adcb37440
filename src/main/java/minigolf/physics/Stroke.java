package minigolf.physics;

import minigolf.course.Bounds;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.terrain.Terrain;

/**
 * One stroke of the ball, advanced one fixed step at a time. The game calls {@link #step()} at
 * 60 Hz to animate it; bots and the command line run it to the end through {@link Simulator}:
 * both use exactly this code.
 *
 * <p>Equations (see docs/course-format.md): classic a = -g grad h - mu_k g v/|v|; complete
 * a = -g grad h/D - mu_k g/sqrt(D) * v/sqrt(|v|^2 + (grad h . v)^2) with D = 1 + |grad h|^2.
 *
 * <p>Stopping is exact: when the ball would stop within the coming step (|v| &lt;= a_par dt,
 * a_par the deceleration along v) the step is finished analytically at constant acceleration
 * and v is set to 0. At rest the ball stays if mu_s &gt; |grad h| (or kinetic friction alone
 * holds it), else it starts rolling down the slope. Water entry and leaving the bounds are
 * located inside the step by bisection on the integrator's own sub-step.
 */
public final class Stroke {
    /** Bisection halvings when locating an event inside a step: dt / 2^50 is far below 1 mm. */
    private static final int LOCATE_ITERATIONS = 50;

    private final Terrain terrain;
    private final FrictionField friction;
    private final Bounds bounds;
    private final double gravity;
    private final boolean complete;
    private final Integrator integrator;
    private final double dt;
    private final double maxTime;
    private final double holeX;
    private final double holeY;
    private final double holeRadius;
    private final boolean captureRule;
    private final double captureSpeed;
    private final TrajectoryListener listener;
    private final boolean zoned;

    // The ball's state and the terrain sample at it (reused as the first stage of the next step).
    private double x, y, vx, vy, t;
    private double h, hx, hy, muK;
    private int steps;

    private Outcome outcome;
    private double endX, endY;

    // Scratch: the last acceleration and the state a sub-step produced.
    private final double[] sample = new double[3];
    private double ax, ay;
    /** While not NaN, the kinetic friction every stage uses (a step that ends at a zone's edge). */
    private double frozenMuK = Double.NaN;
    private double nx, ny, nvx, nvy;

    /**
     * Starts a stroke from (x0, y0) with velocity (vx0, vy0).
     *
     * @throws IllegalArgumentException if the shot is faster than the course's maxSpeed
     */
    public Stroke(World world, SimulationSettings settings, double x0, double y0, double vx0, double vy0,
                  TrajectoryListener listener) {
        PhysicsSettings physics = world.physics();
        double speed = Math.sqrt(vx0 * vx0 + vy0 * vy0);
        if (!Double.isFinite(speed)) {
            throw new IllegalArgumentException("shot velocity must be finite numbers");
        }
        if (speed > physics.maxSpeed() * (1 + 1e-12)) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "shot speed %.3f m/s exceeds the course's maxSpeed of %s m/s", speed, physics.maxSpeed()));
        }
        this.terrain = world.terrain();
        this.friction = world.friction();
        this.bounds = world.bounds();
        this.gravity = physics.gravity();
        this.complete = physics.model() == PhysicsModel.COMPLETE;
        this.integrator = settings.integrator();
        this.dt = settings.dt();
        this.maxTime = settings.maxTime();
        Hole hole = world.hole();
        this.holeX = hole.position().x();
        this.holeY = hole.position().y();
        this.holeRadius = hole.radius();
        this.captureRule = hole.rule() == HoleRule.CAPTURE;
        this.captureSpeed = hole.effectiveCaptureSpeed();
        this.listener = listener;
        this.zoned = friction.hasZones();
        this.x = x0;
        this.y = y0;
        this.vx = vx0;
        this.vy = vy0;
        sampleCurrent();
        if (!bounds.contains(x, y)) {
            finish(Outcome.OUT, x, y);
        } else if (h < 0) {
            finish(Outcome.WATER, x, y);
        }
    }

    public boolean isFinished() {
        return outcome != null;
    }

    /** The result; only valid once {@link #isFinished()}. */
    public ShotResult result() {
        if (outcome == null) throw new IllegalStateException("the stroke has not finished");
        return new ShotResult(outcome, endX, endY, t, steps);
    }

    public double x() { return x; }
    public double y() { return y; }
    public double vx() { return vx; }
    public double vy() { return vy; }
    public double time() { return t; }
    public int steps() { return steps; }
    /** The terrain height under the ball. */
    public double height() { return h; }

    /** Advances the ball by one step (or ends the stroke). Does nothing once finished. */
    public void step() {
        if (outcome != null) return;
        if (t >= maxTime) {
            finish(Outcome.TIMEOUT, x, y);
            return;
        }
        double speed = Math.sqrt(vx * vx + vy * vy);
        if (speed == 0 && staysAtRest()) {
            finish(isInHole(x, y) ? Outcome.HOLED : Outcome.STOPPED, x, y);
            return;
        }
        acceleration(hx, hy, muK, vx, vy);
        double a1x = ax, a1y = ay;
        if (speed > 0) {
            double decelerationAlongV = -(a1x * vx + a1y * vy) / speed;
            if (decelerationAlongV > 0 && speed <= decelerationAlongV * dt && comesToRest(speed)) {
                finishStep(speed / decelerationAlongV, StepKind.STOP, a1x, a1y, speed);
                return;
            }
            // A slow, braking ball: the friction direction would flip inside the integrator's
            // stages (they can cancel and make the ball creep for ever) and, explicit, it would
            // chatter sideways; gravity and friction change v by at most g (|grad h| + mu_k) dt
            // in a step. Such steps treat friction implicitly (see subStep).
            double maxChange = gravity * (Math.sqrt(hx * hx + hy * hy) + muK) * dt;
            if (decelerationAlongV > 0 && speed <= maxChange) {
                finishStep(dt, StepKind.SLOW, a1x, a1y, speed);
                return;
            }
        }
        finishStep(dt, StepKind.INTEGRATOR, a1x, a1y, speed);
    }

    /** Runs the stroke to its end. */
    public ShotResult run() {
        while (outcome == null) step();
        return result();
    }

    /**
     * Whether the continuous model really brings the braking ball to v = 0. Where the slope is
     * steeper than mu_k, gravity turns a ball with any sideways motion round before it stops, and
     * it rolls back down; only a ball moving straight up the slope stops (then mu_s decides).
     */
    private boolean comesToRest(double speed) {
        double slopeSquared = hx * hx + hy * hy;
        if (slopeSquared <= muK * muK) return true;
        double cross = vx * hy - vy * hx;
        double dot = vx * hx + vy * hy;
        return dot > 0 && Math.abs(cross) <= 1e-9 * speed * Math.sqrt(slopeSquared);
    }

    private boolean staysAtRest() {
        double slope = Math.sqrt(hx * hx + hy * hy);
        return friction.staticFriction(x, y) > slope || muK >= slope;
    }

    private boolean isInHole(double px, double py) {
        double dx = px - holeX, dy = py - holeY;
        return dx * dx + dy * dy <= holeRadius * holeRadius;
    }

    /** How a step advances the ball. */
    private enum StepKind {
        /** The chosen integrator (Euler, RK2, RK4). */
        INTEGRATOR,
        /** The analytic last piece of motion at constant acceleration; it ends with v = 0. */
        STOP,
        /** A slow braking ball: gravity explicit, friction implicit (never flips, never chatters). */
        SLOW
    }

    /** Completes a step of length tau of the given kind, with events, and commits it. */
    private void finishStep(double tau, StepKind kind, double a1x, double a1y, double speed0) {
        try {
            if (zoned && kind == StepKind.INTEGRATOR) tau = stopAtZoneEdge(tau, a1x, a1y);
            commitStep(tau, kind, a1x, a1y, speed0);
        } finally {
            frozenMuK = Double.NaN;
        }
    }

    /**
     * Friction jumps at a zone's edge, and an integrator step across the jump loses its order.
     * If the step would end in another zone, it is shortened to end just past the edge, with the
     * friction of the zone it started in; the next step starts with the new zone's friction.
     */
    private double stopAtZoneEdge(double tau, double a1x, double a1y) {
        int zone = friction.zoneAt(x, y);
        subStep(tau, StepKind.INTEGRATOR, a1x, a1y);
        if (friction.zoneAt(nx, ny) == zone) return tau;
        frozenMuK = muK;
        double inside = 0, beyond = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (inside + beyond);
            subStep(mid, StepKind.INTEGRATOR, a1x, a1y);
            if (friction.zoneAt(nx, ny) == zone) inside = mid; else beyond = mid;
        }
        return beyond;
    }

    private void commitStep(double tau, StepKind kind, double a1x, double a1y, double speed0) {
        subStep(tau, kind, a1x, a1y);
        // A stop step ends at rest, and so does a slow step in which friction held the ball.
        boolean stopping = kind == StepKind.STOP || (kind == StepKind.SLOW && nvx == 0 && nvy == 0);
        double endTau = tau;
        Outcome event = hazardAt(nx, ny);
        if (event != null) {
            endTau = locateHazard(tau, kind, a1x, a1y);
            subStep(endTau, kind, a1x, a1y);
            event = hazardAt(nx, ny);
        }
        double speed1 = stopping && event == null ? 0 : Math.sqrt(nvx * nvx + nvy * nvy);
        boolean pathEndsHere = stopping || event != null;
        if (captureRule && captureOnSegment(nx, ny, speed0, speed1, endTau, pathEndsHere)) {
            return;
        }
        x = nx;
        y = ny;
        vx = stopping && event == null ? 0 : nvx;
        vy = stopping && event == null ? 0 : nvy;
        t += endTau;
        steps++;
        if (listener != null) listener.onStep(t, x, y, vx, vy);
        if (event != null) {
            finish(event, x, y);
            return;
        }
        sampleCurrent();
    }

    /** Writes the state after a sub-step of length tau from the current state into n*. */
    private void subStep(double tau, StepKind kind, double a1x, double a1y) {
        if (kind == StepKind.STOP) {
            nx = x + vx * tau + 0.5 * a1x * tau * tau;
            ny = y + vy * tau + 0.5 * a1y * tau * tau;
            nvx = vx + a1x * tau;
            nvy = vy + a1y * tau;
            return;
        }
        if (kind == StepKind.SLOW) {
            slowSubStep(tau);
            return;
        }
        switch (integrator) {
            case EULER -> {
                nx = x + tau * vx;
                ny = y + tau * vy;
                nvx = vx + tau * a1x;
                nvy = vy + tau * a1y;
            }
            case RK2 -> {
                double half = 0.5 * tau;
                double mvx = vx + half * a1x, mvy = vy + half * a1y;
                accelerationAt(x + half * vx, y + half * vy, mvx, mvy);
                nx = x + tau * mvx;
                ny = y + tau * mvy;
                nvx = vx + tau * ax;
                nvy = vy + tau * ay;
            }
            case RK4 -> {
                double half = 0.5 * tau;
                double v2x = vx + half * a1x, v2y = vy + half * a1y;
                accelerationAt(x + half * vx, y + half * vy, v2x, v2y);
                double a2x = ax, a2y = ay;
                double v3x = vx + half * a2x, v3y = vy + half * a2y;
                accelerationAt(x + half * v2x, y + half * v2y, v3x, v3y);
                double a3x = ax, a3y = ay;
                double v4x = vx + tau * a3x, v4y = vy + tau * a3y;
                accelerationAt(x + tau * v3x, y + tau * v3y, v4x, v4y);
                double sixth = tau / 6;
                nx = x + sixth * (vx + 2 * v2x + 2 * v3x + v4x);
                ny = y + sixth * (vy + 2 * v2y + 2 * v3y + v4y);
                nvx = vx + sixth * (a1x + 2 * a2x + 2 * a3x + ax);
                nvy = vy + sixth * (a1y + 2 * a2y + 2 * a3y + ay);
            }
        }
    }

    /**
     * Semi-implicit step for a slow ball: w = v + tau G (gravity's part G of the acceleration),
     * then friction of magnitude F along -v_end, which shortens w by tau F or stops the ball if
     * |w| &lt;= tau F (Coulomb friction as physics engines treat it). Position by the trapezoid rule.
     */
    private void slowSubStep(double tau) {
        double normalisation = complete ? 1 + hx * hx + hy * hy : 1;
        double gx = -gravity * hx / normalisation, gy = -gravity * hy / normalisation;
        double wx = vx + tau * gx, wy = vy + tau * gy;
        double w = Math.sqrt(wx * wx + wy * wy);
        double friction = muK * gravity;
        if (complete) {
            double along = w > 0 ? (hx * wx + hy * wy) / w : Math.sqrt(normalisation - 1);
            friction /= Math.sqrt(normalisation) * Math.sqrt(1 + along * along);
        }
        if (w > tau * friction) {
            double keep = 1 - tau * friction / w;
            nvx = wx * keep;
            nvy = wy * keep;
        } else {
            double pull = Math.sqrt(gx * gx + gy * gy);
            // Friction stops the ball within the step, unless the slope is steeper than kinetic
            // friction can hold: then the ball turns round and starts back down it.
            double net = pull > friction ? 0.5 * tau * (pull - friction) / pull : 0;
            nvx = gx * net;
            nvy = gy * net;
        }
        nx = x + 0.5 * tau * (vx + nvx);
        ny = y + 0.5 * tau * (vy + nvy);
    }

    private Outcome hazardAt(double px, double py) {
        if (!bounds.contains(px, py)) return Outcome.OUT;
        if (terrain.height(px, py) < 0) return Outcome.WATER;
        return null;
    }

    /** The first sub-step length at which the ball is in a hazard, found by bisection. */
    private double locateHazard(double tau, StepKind kind, double a1x, double a1y) {
        double safe = 0, hazard = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (safe + hazard);
            subStep(mid, kind, a1x, a1y);
            if (hazardAt(nx, ny) != null) hazard = mid; else safe = mid;
        }
        return hazard;
    }

    /**
     * The capture rule on the straight segment from the current position to (ex, ey): the ball
     * drops if it passes within the radius at a speed below v_c (1 - (delta/r)^2), delta its
     * closest approach. A segment whose nearest point is its end, while the ball rolls on, leaves
     * the decision to the next segment, where the approach continues.
     */
    private boolean captureOnSegment(double ex, double ey, double speed0, double speed1, double tau,
                                     boolean pathEndsHere) {
        double dx = ex - x, dy = ey - y;
        double lengthSquared = dx * dx + dy * dy;
        double f = lengthSquared == 0 ? 0
                : Math.max(0, Math.min(1, ((holeX - x) * dx + (holeY - y) * dy) / lengthSquared));
        if (f >= 1 && !pathEndsHere) return false;
        double cx = x + f * dx, cy = y + f * dy;
        double delta = Math.hypot(holeX - cx, holeY - cy);
        if (delta >= holeRadius) return false;
        double ratio = delta / holeRadius;
        double speedThere = speed0 + f * (speed1 - speed0);
        if (speedThere >= captureSpeed * (1 - ratio * ratio)) return false;
        x = cx;
        y = cy;
        t += f * tau;
        steps++;
        if (listener != null) listener.onStep(t, x, y, 0, 0);
        finish(Outcome.HOLED, cx, cy);
        return true;
    }

    private void finish(Outcome result, double px, double py) {
        outcome = result;
        endX = px;
        endY = py;
        vx = 0;
        vy = 0;
    }

    private void sampleCurrent() {
        terrain.sample(x, y, sample);
        h = sample[0];
        hx = sample[1];
        hy = sample[2];
        muK = friction.kinetic(x, y);
    }

    private void accelerationAt(double px, double py, double pvx, double pvy) {
        terrain.sample(px, py, sample);
        double mu = Double.isNaN(frozenMuK) ? friction.kinetic(px, py) : frozenMuK;
        acceleration(sample[1], sample[2], mu, pvx, pvy);
    }

    /** The equations of motion: writes (ax, ay) for slope (gx, gy), friction mu and velocity v. */
    private void acceleration(double gx, double gy, double mu, double pvx, double pvy) {
        double speedSquared = pvx * pvx + pvy * pvy;
        double normalisation = complete ? 1 + gx * gx + gy * gy : 1;
        if (speedSquared == 0) {
            // Starting from rest: the limit of the moving equations as v -> 0 along -grad h.
            double slope = Math.sqrt(gx * gx + gy * gy);
            double factor = slope > mu ? -gravity * (1 - mu / slope) / normalisation : 0;
            ax = factor * gx;
            ay = factor * gy;
            return;
        }
        if (complete) {
            double along = gx * pvx + gy * pvy;
            double frictionScale = mu * gravity / (Math.sqrt(normalisation) * Math.sqrt(speedSquared + along * along));
            ax = -gravity * gx / normalisation - frictionScale * pvx;
            ay = -gravity * gy / normalisation - frictionScale * pvy;
        } else {
            double frictionScale = mu * gravity / Math.sqrt(speedSquared);
            ax = -gravity * gx - frictionScale * pvx;
            ay = -gravity * gy - frictionScale * pvy;
        }
    }
}
