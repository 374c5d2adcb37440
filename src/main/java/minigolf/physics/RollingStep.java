package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * The rolling equations and one sub-step of them, from a start state into (nx, ny, nvx, nvy).
 * Equations (docs/course-format.md): classic a = -g grad h - mu_k g v/|v|; complete
 * a = -g grad h/D - mu_k g/sqrt(D) * v/sqrt(|v|^2 + (grad h . v)^2) with D = 1 + |grad h|^2.
 * {@link BallState} holds the ball's state; this class only integrates.
 */
final class RollingStep {
    /** How a step advances the ball. */
    enum Kind {
        /** The chosen integrator (Euler, RK2, RK4). */
        INTEGRATOR,
        /** The analytic last piece of motion at constant acceleration; it ends with v = 0. */
        STOP,
        /** A slow braking ball: gravity explicit, friction implicit (never flips, never chatters). */
        SLOW
    }

    private final Terrain terrain;
    private final FrictionField friction;
    /** Push zones and magnets; null without them. */
    private final ForceField forces;
    private final double gravity;
    private final boolean complete;
    private final Integrator integrator;
    /** Integrator steps longer than this are long steps ({@link #advanceLong}); infinite unless RK4 is controlled. */
    private final double longFrom;
    private final double[] sample = new double[3];
    private final double[] force = new double[2];
    private final double[] pull = new double[2];

    // The start state of the sub-steps: position, velocity, slope, kinetic friction and force there.
    private double x, y, vx, vy, hx, hy, muK, fx, fy;
    /** While not NaN, the kinetic friction every stage uses (a step that ends at a zone's edge). */
    double frozenMuK = Double.NaN;
    /** While set, the push every stage uses (a step that ends at a push zone's edge): frozenPushX, frozenPushY. */
    boolean pushFrozen;
    double frozenPushX, frozenPushY;
    /**
     * While set, a long step's stages take the start's force (fx, fy) instead of asking the push
     * zones and magnets at each point: the caller found that force the same all over the step's
     * reach (inside one push zone or clear of them all, no magnet near); a stage that strays out of
     * that reach vetoes the step anyway (RollingPhase.clearOfHazards).
     */
    boolean uniformForce;
    /** Whether the long step being integrated takes the start's force ({@link #uniformForce}). */
    private boolean stagesUniform;
    /**
     * While leaning, the ball rolls along an obstacle whose horizontal normal (pointing away from
     * it) is (leanX, leanY): the obstacle takes the part of the acceleration that pushes into it.
     */
    boolean leaning;
    double leanX, leanY;
    /** The last acceleration computed. */
    double ax, ay;
    /** The state a sub-step produced. */
    double nx, ny, nvx, nvy;
    // The last RK4 sub-step's fourth-stage velocity and its length, for errorEstimate.
    private double stage4vx, stage4vy, lastTau;
    /** The last long step ({@link #advanceLong}): the lowest ground its stages sampled, and the box round their points. */
    double stageLowest, stageMinX, stageMinY, stageMaxX, stageMaxY;
    /** The last long step's steepest ground among its stages (|grad h| squared; the pull gradient's with forces). */
    double stageSteepest;
    /**
     * The last RK4 or long step's ground bending away along the start's velocity v, as its stages saw it:
     * the largest drop of the terrain's slope along v from the start's, grad h(start) . v -
     * grad h(stage) . v, divided by the stage's fraction of the step (m/s); about tau v^T H v
     * with the sign turned, where the ground curves away ({@link TakeOff#gentleAlong}).
     */
    double stageBend;
    /** The stages a long step sampled, in the order of their times (the last is its end): the fraction of the step, position, height. */
    static final double[] STAGE_TIMES = {0.2, 0.3, 0.8, 8.0 / 9, 1, 1};
    final double[] stageX = new double[STAGE_TIMES.length], stageY = new double[STAGE_TIMES.length],
            stageH = new double[STAGE_TIMES.length];
    /** The last long step's error estimate (position, m). */
    private double longError;

    /**
     * @param dt the base step: RK4 steps longer than it are long steps ({@link #advanceLong}); with
     *           Euler and RK2 every step is theirs
     */
    RollingStep(Terrain terrain, FrictionField friction, ForceField forces, double gravity, boolean complete,
                Integrator integrator, double dt) {
        this.terrain = terrain;
        this.friction = friction;
        this.forces = forces;
        this.gravity = gravity;
        this.complete = complete;
        this.integrator = integrator;
        this.longFrom = integrator == Integrator.RK4 ? dt * (1 + 1e-9) : Double.POSITIVE_INFINITY;
    }

    /** A new stroke: no frozen friction or push, not leaning. */
    void reset() {
        frozenMuK = Double.NaN;
        pushFrozen = false;
        uniformForce = false;
        leaning = false;
    }

    /** The shared last terrain sample: a long step's end is sampled by its last stage. */
    private GroundCache cache;

    void share(GroundCache ground) {
        this.cache = ground;
    }

    /** Sets the start state of the following sub-steps (fx, fy: the force of push zones and magnets there). */
    void from(double x, double y, double vx, double vy, double hx, double hy, double muK, double fx, double fy) {
        this.x = x;
        this.y = y;
        this.vx = vx;
        this.vy = vy;
        this.hx = hx;
        this.hy = hy;
        this.muK = muK;
        this.fx = fx;
        this.fy = fy;
    }

    /** Writes the state after a sub-step of length tau from the current state into n*. */
    void advance(double tau, Kind kind, double a1x, double a1y) {
        if (kind == Kind.STOP) {
            nx = x + vx * tau + 0.5 * a1x * tau * tau;
            ny = y + vy * tau + 0.5 * a1y * tau * tau;
            nvx = vx + a1x * tau;
            nvy = vy + a1y * tau;
            return;
        }
        if (kind == Kind.SLOW) {
            slowSubStep(tau);
            return;
        }
        if (tau > longFrom) {
            advanceLong(tau, a1x, a1y);
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
                double along = hx * vx + hy * vy, bend = 2 * (along - sample[1] * vx - sample[2] * vy);
                double a2x = ax, a2y = ay;
                double v3x = vx + half * a2x, v3y = vy + half * a2y;
                accelerationAt(x + half * v2x, y + half * v2y, v3x, v3y);
                bend = Math.max(bend, 2 * (along - sample[1] * vx - sample[2] * vy));
                double a3x = ax, a3y = ay;
                double v4x = vx + tau * a3x, v4y = vy + tau * a3y;
                accelerationAt(x + tau * v3x, y + tau * v3y, v4x, v4y);
                stageBend = Math.max(bend, along - sample[1] * vx - sample[2] * vy);
                double sixth = tau / 6;
                nx = x + sixth * (vx + 2 * v2x + 2 * v3x + v4x);
                ny = y + sixth * (vy + 2 * v2y + 2 * v3y + v4y);
                nvx = vx + sixth * (a1x + 2 * a2x + 2 * a3x + ax);
                nvy = vy + sixth * (a1y + 2 * a2y + 2 * a3y + ay);
                stage4vx = v4x;
                stage4vy = v4y;
                lastTau = tau;
            }
        }
    }

    // The Dormand-Prince 5(4) pair (Dormand & Prince 1980): stage coefficients, the fifth-order
    // weights (those of the last stage row) and the error weights (fifth minus fourth order).
    private static final double A21 = 1.0 / 5;
    private static final double A31 = 3.0 / 40, A32 = 9.0 / 40;
    private static final double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
    private static final double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729;
    private static final double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176,
            A65 = -5103.0 / 18656;
    private static final double B1 = 35.0 / 384, B3 = 500.0 / 1113, B4 = 125.0 / 192, B5 = -2187.0 / 6784, B6 = 11.0 / 84;
    private static final double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200,
            E6 = 22.0 / 525, E7 = -1.0 / 40;

    /**
     * A long step (longer than dt, where nothing is within its reach: docs/physics.md, "Step
     * control") by the fifth-order Dormand-Prince formula, from the current state into n*; a1 is
     * the acceleration at the start. Its embedded fourth-order solution gives the error estimate
     * ({@link #longErrorEstimate}), for which the seventh stage samples the end. The stages'
     * lowest ground and the box round their points are kept for the hazard checks.
     */
    void advanceLong(double tau, double a1x, double a1y) {
        double h = tau;
        stagesUniform = uniformForce;
        double p2x = x + h * A21 * vx, p2y = y + h * A21 * vy;
        double v2x = vx + h * A21 * a1x, v2y = vy + h * A21 * a1y;
        accelerationAt(p2x, p2y, v2x, v2y);
        keepStage(0, p2x, p2y);
        double a2x = ax, a2y = ay, lowest = sample[0], steepest = steepness();
        double along = hx * vx + hy * vy, bend = (along - sample[1] * vx - sample[2] * vy) * 5;
        double minX = Math.min(x, p2x), maxX = Math.max(x, p2x), minY = Math.min(y, p2y), maxY = Math.max(y, p2y);
        double p3x = x + h * (A31 * vx + A32 * v2x), p3y = y + h * (A31 * vy + A32 * v2y);
        double v3x = vx + h * (A31 * a1x + A32 * a2x), v3y = vy + h * (A31 * a1y + A32 * a2y);
        accelerationAt(p3x, p3y, v3x, v3y);
        keepStage(1, p3x, p3y);
        bend = Math.max(bend, (along - sample[1] * vx - sample[2] * vy) * (10.0 / 3));
        double a3x = ax, a3y = ay;
        lowest = Math.min(lowest, sample[0]);
        steepest = Math.max(steepest, steepness());
        double p4x = x + h * (A41 * vx + A42 * v2x + A43 * v3x), p4y = y + h * (A41 * vy + A42 * v2y + A43 * v3y);
        double v4x = vx + h * (A41 * a1x + A42 * a2x + A43 * a3x), v4y = vy + h * (A41 * a1y + A42 * a2y + A43 * a3y);
        accelerationAt(p4x, p4y, v4x, v4y);
        keepStage(2, p4x, p4y);
        bend = Math.max(bend, (along - sample[1] * vx - sample[2] * vy) * 1.25);
        double a4x = ax, a4y = ay;
        lowest = Math.min(lowest, sample[0]);
        steepest = Math.max(steepest, steepness());
        double p5x = x + h * (A51 * vx + A52 * v2x + A53 * v3x + A54 * v4x);
        double p5y = y + h * (A51 * vy + A52 * v2y + A53 * v3y + A54 * v4y);
        double v5x = vx + h * (A51 * a1x + A52 * a2x + A53 * a3x + A54 * a4x);
        double v5y = vy + h * (A51 * a1y + A52 * a2y + A53 * a3y + A54 * a4y);
        accelerationAt(p5x, p5y, v5x, v5y);
        keepStage(3, p5x, p5y);
        bend = Math.max(bend, (along - sample[1] * vx - sample[2] * vy) * (9.0 / 8));
        double a5x = ax, a5y = ay;
        lowest = Math.min(lowest, sample[0]);
        steepest = Math.max(steepest, steepness());
        double p6x = x + h * (A61 * vx + A62 * v2x + A63 * v3x + A64 * v4x + A65 * v5x);
        double p6y = y + h * (A61 * vy + A62 * v2y + A63 * v3y + A64 * v4y + A65 * v5y);
        double v6x = vx + h * (A61 * a1x + A62 * a2x + A63 * a3x + A64 * a4x + A65 * a5x);
        double v6y = vy + h * (A61 * a1y + A62 * a2y + A63 * a3y + A64 * a4y + A65 * a5y);
        accelerationAt(p6x, p6y, v6x, v6y);
        keepStage(4, p6x, p6y);
        bend = Math.max(bend, along - sample[1] * vx - sample[2] * vy);
        double a6x = ax, a6y = ay;
        lowest = Math.min(lowest, sample[0]);
        steepest = Math.max(steepest, steepness());
        nx = x + h * (B1 * vx + B3 * v3x + B4 * v4x + B5 * v5x + B6 * v6x);
        ny = y + h * (B1 * vy + B3 * v3y + B4 * v4y + B5 * v5y + B6 * v6y);
        nvx = vx + h * (B1 * a1x + B3 * a3x + B4 * a4x + B5 * a5x + B6 * a6x);
        nvy = vy + h * (B1 * a1y + B3 * a3y + B4 * a4y + B5 * a5y + B6 * a6y);
        accelerationAt(nx, ny, nvx, nvy);
        stagesUniform = false;
        keepStage(5, nx, ny);
        if (cache != null) cache.keep(nx, ny, sample[0], sample[1], sample[2]);
        lowest = Math.min(lowest, sample[0]);
        steepest = Math.max(steepest, steepness());
        double ex = h * (E1 * vx + E3 * v3x + E4 * v4x + E5 * v5x + E6 * v6x + E7 * nvx);
        double ey = h * (E1 * vy + E3 * v3y + E4 * v4y + E5 * v5y + E6 * v6y + E7 * nvy);
        longError = Math.sqrt(ex * ex + ey * ey);
        stageLowest = lowest;
        stageSteepest = steepest;
        stageBend = Math.max(bend, along - sample[1] * vx - sample[2] * vy);
        minX = Math.min(Math.min(minX, Math.min(p3x, p4x)), Math.min(Math.min(p5x, p6x), nx));
        maxX = Math.max(Math.max(maxX, Math.max(p3x, p4x)), Math.max(Math.max(p5x, p6x), nx));
        minY = Math.min(Math.min(minY, Math.min(p3y, p4y)), Math.min(Math.min(p5y, p6y), ny));
        maxY = Math.max(Math.max(maxY, Math.max(p3y, p4y)), Math.max(Math.max(p5y, p6y), ny));
        stageMinX = minX;
        stageMinY = minY;
        stageMaxX = maxX;
        stageMaxY = maxY;
    }

    private void keepStage(int k, double px, double py) {
        stageX[k] = px;
        stageY[k] = py;
        stageH[k] = sample[0];
    }

    /** The position error of the last long step: its fifth- minus fourth-order solution. */
    double longErrorEstimate() {
        return longError;
    }

    /**
     * Semi-implicit step for a slow ball: w = v + tau G (gravity's part G of the acceleration),
     * then friction of magnitude F along -v_end, which shortens w by tau F or stops the ball if
     * |w| &lt;= tau F (Coulomb friction as physics engines treat it). Position by the trapezoid rule.
     */
    private void slowSubStep(double tau) {
        slowSubStep(tau, hx, hy, fx, fy);
        terrain.sample(nx, ny, sample);
        double endHx = sample[1], endHy = sample[2];
        double startX = hx, startY = hy, endX = endHx, endY = endHy, endFx = fx, endFy = fy;
        if (forces != null) {
            forceAt(nx, ny);
            endFx = force[0];
            endFy = force[1];
            ForceField.pullGradient(endHx, endHy, endFx, endFy, gravity, complete, force);
            endX = force[0];
            endY = force[1];
            ForceField.pullGradient(hx, hy, fx, fy, gravity, complete, force);
            startX = force[0];
            startY = force[1];
        }
        if (startX * endX + startY * endY < 0) {
            // The pull turned over within the step: a valley's floor or a crease lies between (or
            // two pushes meet). Gravity from the start alone would throw the ball up the far side (in
            // a V-shaped valley, higher every step: energy from nowhere); the mean of both ends' does not.
            slowSubStep(tau, 0.5 * (hx + endHx), 0.5 * (hy + endHy), 0.5 * (fx + endFx), 0.5 * (fy + endFy));
        }
    }

    private void slowSubStep(double tau, double hx, double hy, double fx, double fy) {
        double normalisation = complete ? 1 + hx * hx + hy * hy : 1;
        double gx, gy;
        if (fx == 0 && fy == 0) {
            gx = -gravity * hx / normalisation;
            gy = -gravity * hy / normalisation;
        } else {
            ForceField.pullGradient(hx, hy, fx, fy, gravity, complete, force);
            gx = -gravity * force[0] / normalisation;
            gy = -gravity * force[1] / normalisation;
        }
        if (leaning) {
            double into = gx * leanX + gy * leanY;
            if (into < 0) {
                gx -= into * leanX;
                gy -= into * leanY;
            }
        }
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
            nx = x + 0.5 * tau * (vx + nvx);
            ny = y + 0.5 * tau * (vy + nvy);
            return;
        }
        // Friction stops the ball within the step, at about t0 = |v| / (friction + the pull against
        // v), unless the slope is steeper than kinetic friction can hold: then the ball turns
        // round there and rolls back down for the rest of the step, with the friction of a ball
        // rolling straight down (mu_k g / D in the complete model). Whether a turning ball stops
        // instead is the rest rule's decision, not this step's. The position follows the two
        // straight pieces of velocity, so the ball never climbs higher than its speed can take it.
        double speed = Math.sqrt(vx * vx + vy * vy);
        double pull = Math.sqrt(gx * gx + gy * gy);
        double against = speed > 0 ? friction - (gx * vx + gy * vy) / speed : friction;
        double t0 = speed > 0 && against > 0 ? Math.min(tau, speed / against) : 0;
        double downhill = muK * gravity / normalisation;
        double net = pull > downhill ? (tau - t0) * (pull - downhill) / pull : 0;
        nvx = gx * net;
        nvy = gy * net;
        nx = x + 0.5 * (vx * t0 + nvx * (tau - t0));
        ny = y + 0.5 * (vy * t0 + nvy * (tau - t0));
    }

    /**
     * The position error of the last RK4 sub-step, estimated from its embedded third-order
     * solution y + tau/6 (k1 + 2 k2 + 2 k3 + k5), k5 the slope at the step's end (first same as
     * last): RK4 minus that is tau/6 (k4 - k5). For the position k4 is the fourth stage's
     * velocity v + tau a3 and k5 the end's velocity, so the estimate costs no terrain sample. It
     * is of third order's error, O(tau^4), and overstates RK4's own on smooth ground; where the
     * ground's curvature jumps inside the step (a grid's cell edge) both are larger.
     */
    double errorEstimate() {
        double ex = stage4vx - nvx, ey = stage4vy - nvy;
        return lastTau / 6 * Math.sqrt(ex * ex + ey * ey);
    }

    /** |grad h| squared of the last sample; with push zones or magnets, of the pull gradient there (the force of the last sample). */
    private double steepness() {
        if (forces == null) return sample[1] * sample[1] + sample[2] * sample[2];
        ForceField.pullGradient(sample[1], sample[2], force[0], force[1], gravity, complete, pull);
        return pull[0] * pull[0] + pull[1] * pull[1];
    }

    private void accelerationAt(double px, double py, double pvx, double pvy) {
        terrain.sample(px, py, sample);
        double mu = Double.isNaN(frozenMuK) ? friction.kinetic(px, py) : frozenMuK;
        if (forces == null) {
            acceleration(sample[1], sample[2], 0, 0, mu, pvx, pvy);
            return;
        }
        forceAt(px, py);
        acceleration(sample[1], sample[2], force[0], force[1], mu, pvx, pvy);
    }

    /** The force of the push zones (or the frozen push) and the magnets at (px, py) into force[0..1]. */
    private void forceAt(double px, double py) {
        if (stagesUniform) {
            force[0] = fx;
            force[1] = fy;
            return;
        }
        if (pushFrozen) {
            force[0] = frozenPushX;
            force[1] = frozenPushY;
        } else {
            forces.push(px, py, force);
        }
        forces.addMagnets(px, py, force);
    }

    /**
     * The equations of motion: writes (ax, ay) for slope (gx, gy), the force (fx, fy) of push zones
     * and magnets, friction mu and velocity v; while leaning on an obstacle, without the part that
     * pushes into it. The force acts as a tilt would (ForceField.pullGradient): classic
     * a = -g grad h + f - friction; complete a = -g grad h/D + f - grad h (grad h . f)/D - friction.
     */
    void acceleration(double gx, double gy, double fx, double fy, double mu, double pvx, double pvy) {
        // The common case (a moving ball, no force, not leaning) is kept small enough for the JIT
        // to inline into every stage of a step.
        double speedSquared = pvx * pvx + pvy * pvy;
        if (fx == 0 && fy == 0 && !leaning && speedSquared != 0) {
            moving(gx, gy, gx, gy, complete ? 1 + gx * gx + gy * gy : 1, mu, pvx, pvy, speedSquared);
        } else {
            accelerationInGeneral(gx, gy, fx, fy, mu, pvx, pvy, speedSquared);
        }
    }

    private void accelerationInGeneral(double gx, double gy, double fx, double fy, double mu, double pvx, double pvy,
                                       double speedSquared) {
        double normalisation = complete ? 1 + gx * gx + gy * gy : 1;
        // Gravity's and the force's pull, as a gradient (px, py): a = -g p / D before friction.
        double px = gx, py = gy;
        if (fx != 0 || fy != 0) {
            if (complete) {
                double lift = 1 + (gx * fx + gy * fy) / gravity;
                px = gx * lift - normalisation * fx / gravity;
                py = gy * lift - normalisation * fy / gravity;
            } else {
                px = gx - fx / gravity;
                py = gy - fy / gravity;
            }
        }
        if (speedSquared == 0) {
            // Starting from rest: the limit of the moving equations as v -> 0 along -p.
            double slope = Math.sqrt(px * px + py * py);
            double factor = slope > mu ? -gravity * (1 - mu / slope) / normalisation : 0;
            ax = factor * px;
            ay = factor * py;
        } else {
            moving(gx, gy, px, py, normalisation, mu, pvx, pvy, speedSquared);
        }
        if (leaning) {
            double into = ax * leanX + ay * leanY;
            if (into < 0) {
                ax -= into * leanX;
                ay -= into * leanY;
            }
        }
    }

    /** (ax, ay) for a moving ball on slope (gx, gy) under the pull gradient (px, py), D = normalisation. */
    private void moving(double gx, double gy, double px, double py, double normalisation, double mu,
                        double pvx, double pvy, double speedSquared) {
        if (complete) {
            double along = gx * pvx + gy * pvy;
            double frictionScale = mu * gravity / (Math.sqrt(normalisation) * Math.sqrt(speedSquared + along * along));
            ax = -gravity * px / normalisation - frictionScale * pvx;
            ay = -gravity * py / normalisation - frictionScale * pvy;
        } else {
            double frictionScale = mu * gravity / Math.sqrt(speedSquared);
            ax = -gravity * px - frictionScale * pvx;
            ay = -gravity * py - frictionScale * pvy;
        }
    }
}
