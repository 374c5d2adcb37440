package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * The rolling pieces of a stroke. A piece decides what kind of step the ball takes (none at rest,
 * the analytic stop, the slow implicit step, or the integrator's, error-controlled with RK4),
 * integrates it as a trial, cuts it at the first thing that happens inside it (take-off, a zone's
 * edge, a hazard, the end of an obstacle it leans on, an obstacle, the hole) and commits it, which
 * the energy guard may still rewrite.
 */
final class RollingPhase {
    private final BallState ball;
    private final StrokeReports reports;
    private final RollingStep rolling;
    private final RollingTrial trial;
    /** The RK4 step's error control; null for the other integrators. */
    private final StepControl control;
    private final StepLocator locate;
    private final RestRule rest;
    private final TakeOff takeOff;
    private final HoleRules hole;
    private final EnergyGuard energy;
    /** The obstacles and the ball settled against one; null without obstacles. */
    private final Solids scene;
    private final Leaning lean;
    private final PathSweep paths;
    private final ObstacleContact contact;
    private final Terrain terrain;
    private final double gravity;
    private final double ballRadius;
    /** The base step (the frame, 1/60 s by default); longer steps only where {@link #mayStepLong} allows. */
    private final double dt;
    private final double maxTime;
    /** Whether the course has friction zones or push zones, whose edges cut steps. */
    private final boolean zoned;
    /** Whether RK4's error control chooses the steps' lengths. */
    private final boolean controlled;
    /** Whether the ground is smooth (no crease, no cell edge): only there may steps be longer than dt. */
    private final boolean smooth;
    private final FrictionField friction;
    /** Whether the hole's capture rule is checked along every step. */
    private final boolean captureRule;
    /** The teleports; null without them. */
    private final Teleporter teleporter;
    /** While a resting ball waits for a moving obstacle to reach it: the clock of the contact (else NaN). */
    private double waitUntil = Double.NaN;
    private final minigolf.collision.Hit waitHit = new minigolf.collision.Hit();
    /** Push zones and magnets; null without them. */
    private final ForceField forces;
    /** The course clock when the stroke began. */
    private double startClock;
    /** The closed-form stop on shallow ground; null where it does not apply (see Stroke). */
    private final StoppingTail tail;

    RollingPhase(BallState ball, StrokeReports reports, RollingStep rolling, RollingTrial trial, StepControl control,
                 StepLocator locate, RestRule rest, TakeOff takeOff, HoleRules hole, EnergyGuard energy,
                 Solids scene, Leaning lean, PathSweep paths, ObstacleContact contact, Terrain terrain,
                 FrictionField friction, ForceField forces, Teleporter teleporter, PlayArea area, StoppingTail tail,
                 double gravity, double ballRadius, double dt, double maxTime) {
        this.teleporter = teleporter;
        this.forces = forces;
        this.ball = ball;
        this.reports = reports;
        this.rolling = rolling;
        this.trial = trial;
        this.control = control;
        this.locate = locate;
        this.rest = rest;
        this.takeOff = takeOff;
        this.hole = hole;
        this.energy = energy;
        this.scene = scene;
        this.lean = lean;
        this.paths = paths;
        this.contact = contact;
        this.terrain = terrain;
        this.gravity = gravity;
        this.ballRadius = ballRadius;
        this.dt = dt;
        this.maxTime = maxTime;
        this.friction = friction;
        this.zoned = friction.hasZones() || (forces != null && forces.hasPushZones());
        this.controlled = control != null;
        this.smooth = terrain.isSmooth() && !area.hasDeletedCells();
        this.captureRule = hole.captureRule;
        this.tail = tail;
        if (tail != null) tail.reach = (minX, minY, maxX, maxY) -> elementNear(minX, minY, maxX, maxY)
                || (captureRule && hole.near(minX, minY, maxX, maxY));
    }

    /**
     * A new stroke played at course clock {@code clock}: no wait for a moving obstacle, the teleports'
     * exits from the first; {@code strokeKey} summarises the shot for the teleports that draw their exits.
     */
    void start(double clock, long strokeKey) {
        startClock = clock;
        waitUntil = Double.NaN;
        lastClear = 0;
        if (teleporter != null) teleporter.reset(strokeKey);
        if (tail != null) tail.reset();
    }

    /** One rolling piece of at most tau seconds; returns the time it took. */
    double piece(double tau) {
        BallState b = ball;
        if (b.t >= maxTime) {
            reports.finish(Outcome.TIMEOUT, b.x, b.y, b.z);
            return 0;
        }
        // The time limit ends the stroke exactly (a preview of its first seconds ends there).
        if (tau > maxTime - b.t) tau = maxTime - b.t;
        if (teleporter != null) {
            // A ball that landed in a teleport's entry (or was put there) is sent on at once.
            int k = teleporter.at();
            if (k >= 0) {
                if (lean != null) lean.release();
                rest.forget();
                teleporter.send(k);
                reports.state();
                b.pieceTime = 0;
                b.resume = true;
                return 0;
            }
        }
        double speed = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
        // A ball leaning on an obstacle leaves it at rest, where the ground no longer pulls it
        // towards it, or where the obstacle is out of reach (its end).
        boolean leaning = lean != null && lean.active();
        if (leaning && (speed == 0 || !lean.holds(b.x, b.y, b.pullX, b.pullY))) {
            lean.release();
            leaning = false;
        }
        // A ball the rest rule sends back down (it turned faster than REST_SPEED) is not at rest
        // when an energy cut leaves it at v = 0 at its turn: it starts down again, once.
        boolean sentBack = speed == 0 && rest.rollsBack();
        if (sentBack) rest.forget();
        if (speed == 0 && !sentBack && rest.holds(b.x, b.y, b.h, b.pullX, b.pullY, b.muK)) {
            boolean holed = hole.isInHole(b.x, b.y);
            if (!holed && scene != null && scene.hasMoving()) return waitForMoving(tau);
            reports.finish(holed ? Outcome.HOLED : b.restsInHazard() ? Outcome.WATER : Outcome.STOPPED, b.x, b.y, b.z);
            return 0;
        }
        waitUntil = Double.NaN;
        clearMinX = Double.NaN;
        rolling.acceleration(b.hx, b.hy, b.fx, b.fy, b.muK, b.vx, b.vy);
        double a1x = rolling.ax, a1y = rolling.ay;
        if (speed > 0) {
            double decelerationAlongV = -(a1x * b.vx + a1y * b.vy) / speed;
            // The rule sees the pull gradient (the ground's, tilted by push zones and magnets);
            // leaning, without the part the obstacle takes.
            double ghx = b.pullX, ghy = b.pullY;
            if (leaning) {
                lean.effective(b.pullX, b.pullY);
                ghx = lean.gx;
                ghy = lean.gy;
            }
            double slope = Math.sqrt(ghx * ghx + ghy * ghy);
            // A slow ball on ground shallower than mu_k, with nothing near, stops in one closed-form piece.
            if (tail != null && !leaning && slope < b.muK && tail.stops(speed)) return b.pieceTime;
            if (controlled && control.isLong(tau)) tau = longestStep(tau, speed, slope, b.muK, leaning, a1x, a1y);
            b.pieceTime = tau;
            // The stop looks a fixed time ahead and the slow step is that long, whatever length the
            // control has chosen: a ball the control keeps at dt/8 must still stop, not creep in
            // RK4 steps whose stages flip friction (docs/physics.md, "Step control").
            double ahead = Math.min(controlled ? StepControl.STOP_AHEAD * dt : dt, maxTime - b.t);
            if (decelerationAlongV > 0) {
                double stop = rest.stopWithin(ahead, speed, decelerationAlongV, slope, b.vx, b.vy, ghx, ghy, b.muK);
                if (stop >= 0) {
                    finishStep(stop, RollingStep.Kind.STOP, a1x, a1y, speed);
                    return b.pieceTime;
                }
            } else {
                rest.forget();
            }
            // A slow, braking ball: the friction direction would flip inside the integrator's
            // stages (they can cancel and make the ball creep for ever) and, explicit, it would
            // chatter sideways; gravity and friction change v by at most g (|grad h| + mu_k) dt
            // in a step. Such steps treat friction implicitly (RollingStep.Kind.SLOW).
            double maxChange = gravity * (slope + b.muK) * dt * (controlled ? StepControl.SLOW_FRACTION : 1);
            if (decelerationAlongV > 0 && speed <= maxChange) {
                b.pieceTime = ahead;
                finishStep(ahead, RollingStep.Kind.SLOW, a1x, a1y, speed);
                return b.pieceTime;
            }
        } else if (controlled && control.isLong(tau)) {
            tau = dt; // starting from rest
        }
        double whole = tau;
        if (controlled) {
            tau = trial.controlledLength(tau, a1x, a1y);
            if (control.isLong(tau) && !clearOfHazards(tau)) {
                // A long step whose stages met water or the bounds is tried again ending short of
                // them, where its stages put the crossing; the steps of dt then meet it.
                double shore = hazardVeto ? shoreLength(tau) : 0;
                boolean ashore = false;
                if (control.isLong(shore)) {
                    tau = trial.controlledLength(shore, a1x, a1y);
                    ashore = control.isLong(tau) && clearOfHazards(tau);
                }
                control.limit(dt);
                if (!ashore) tau = trial.controlledLength(dt, a1x, a1y);
            }
        }
        b.pieceTime = tau;
        finishStep(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y, speed);
        if (tau < whole && !b.resume && b.outcome == null) {
            b.resume = true;
            b.subPiece = true;
        }
        return b.pieceTime;
    }

    /**
     * A ball the ground holds at rest, on a course with moving obstacles: it stays (the stroke
     * ends) only if no moving obstacle will ever reach it; otherwise it waits, still, until one
     * does (within a period: they repeat) and is hit (docs/course-format.md, "Moving obstacles").
     */
    private double waitForMoving(double tau) {
        BallState b = ball;
        double now = startClock + b.t;
        if (Double.isNaN(waitUntil)) {
            waitUntil = scene.stillContact(b.x, b.y, b.h + ballRadius, now, waitHit);
        }
        if (waitUntil == Double.POSITIVE_INFINITY) {
            waitUntil = Double.NaN;
            reports.finish(Outcome.STOPPED, b.x, b.y, b.z);
            return 0;
        }
        double wait = waitUntil - now;
        if (wait >= tau) {
            b.t += tau;
            b.pieceTime = tau;
            reports.state();
            return tau;
        }
        b.t = waitUntil - startClock;
        waitUntil = Double.NaN;
        paths.hit.set(waitHit);
        contact.whileRolling();
        reports.state();
        b.pieceTime = Math.max(0, wait);
        b.resume = true;
        return b.pieceTime;
    }

    /**
     * How far (m) a long step keeps clear of anything near, beyond the bound of its path's cubic:
     * the cubic is the path only to within its own interpolation error (micrometres at 8 dt), so
     * a contact or a zone's edge is always met by steps of dt, located as they always were.
     */
    static final double PATH_MARGIN = 1e-3;

    /**
     * Whether the long step being chosen starts on ground shallower than mu_k, where the ball
     * cannot turn: it may come nearer its stop (clearOfHazards checks that it stayed so).
     */
    private boolean shallowStep;

    /**
     * The longest step up to tau that may be taken from here (docs/physics.md, "Step control"):
     * dt, or longer where nothing it could reach needs the step's own length. A long step stays on
     * smooth ground, clear of obstacles (still, gates, moving: their reach over a whole period),
     * friction zones' and push zones' edges, magnets, teleports' entries and (under the capture
     * rule) the hole, by the box round its path (a straight line widened by what the acceleration
     * can bend it; clearOfHazards checks the path's own box); the ball leans on no obstacle, and is fast enough that it can neither stop within
     * the step nor come within the rest rule's horizon of a turn (on ground shallower than mu_k it
     * cannot turn: only the stop counts). Cut from tau to the length that qualifies.
     */
    private double longestStep(double tau, double speed, double slope, double muK, boolean leaning,
                               double a1x, double a1y) {
        shallowStep = false;
        clearMinX = Double.NaN;
        if (!smooth || leaning) return dt;
        // Braking at most g (|grad h| + mu_k), it must be left with the speed the rest rule's turn
        // horizon and a step of dt need (the ground may grow steeper than mu_k within the step).
        double braking = gravity * (slope + muK);
        // On ground no steeper than mu_k the ball cannot turn, only stop: the turn horizon is not
        // needed (clearOfHazards checks that every stage's ground stayed that shallow).
        shallowStep = slope < muK;
        double spare = speed - RestRule.REST_SPEED - braking * (dt + (shallowStep ? 0 : RestRule.TURN_HORIZON));
        if (braking * tau >= spare) tau = spare / braking;
        if (!control.isLong(tau)) return dt;
        if (!(scene != null || zoned || captureRule || forces != null || teleporter != null)) return tau;
        // The longest, then halving down to 2 dt: the longest of them with nothing within the
        // step's reach, the box round the straight path at the starting velocity, widened by
        // what the acceleration (twice the start's) can bend the path away from it. The boxes
        // are nested and a box inside one with nothing near has nothing near, so the search
        // starts at the length the last step found (neighbouring steps find about the same) and
        // moves up or down from there: the same length as asking from the longest down.
        int n = 0;
        double length = tau;
        levels[n++] = length;
        while (true) {
            double shorter = 2 * dt;
            while (2 * shorter < length * (1 - 1e-9)) shorter *= 2;
            if (!(shorter < length * (1 - 1e-9)) || !control.isLong(shorter)) break;
            length = shorter;
            levels[n++] = length;
        }
        double acceleration = Math.sqrt(a1x * a1x + a1y * a1y);
        int j = 0;
        while (j < n - 1 && levels[j] > lastClear) j++;
        if (clearWithin(levels[j], acceleration)) {
            while (j > 0 && clearWithin(levels[j - 1], acceleration)) j--;
        } else {
            do {
                j++;
            } while (j < n && !clearWithin(levels[j], acceleration));
            if (j == n) {
                lastClear = 0;
                return dt;
            }
        }
        lastClear = levels[j];
        // Its box, for clearOfHazards.
        clearWithin(levels[j], acceleration, true);
        // No push zone's edge or magnet within reach: the force is the start's all over it.
        rolling.uniformForce = forces != null;
        return levels[j];
    }

    /** The lengths longestStep tries, longest first (tau, then powers of two of 2 dt). */
    private final double[] levels = new double[64];
    /** The length the last longestStep found (0: none, dt); where the next one starts looking. */
    private double lastClear;
    /**
     * The box round the path (centre positions) within which the last long step was found to
     * have nothing near (empty where none was: NaN): a box of clearOfHazards inside it has
     * nothing near either.
     */
    private double clearMinX = Double.NaN, clearMinY, clearMaxX, clearMaxY;

    /** Whether nothing that needs a step's own length is within reach of a step of this length (longestStep). */
    private boolean clearWithin(double length, double acceleration) {
        return clearWithin(length, acceleration, false);
    }

    private boolean clearWithin(double length, double acceleration, boolean keep) {
        BallState b = ball;
        double bend = acceleration * length * length + PATH_MARGIN;
        double ex = b.vx * length, ey = b.vy * length;
        double minX = b.x + Math.min(0, ex) - bend, maxX = b.x + Math.max(0, ex) + bend;
        double minY = b.y + Math.min(0, ey) - bend, maxY = b.y + Math.max(0, ey) + bend;
        if (keep) {
            clearMinX = minX;
            clearMinY = minY;
            clearMaxX = maxX;
            clearMaxY = maxY;
            return true;
        }
        return !elementNear(minX, minY, maxX, maxY) && !(captureRule && hole.near(minX, minY, maxX, maxY));
    }

    /**
     * Whether anything that a step's own length must follow reaches into the rectangle of centre
     * positions: an obstacle (still, a gate, or a moving one anywhere in its period), a friction
     * zone's edge, a push zone's edge or a magnet, a teleport's entry.
     */
    private boolean elementNear(double minX, double minY, double maxX, double maxY) {
        return (scene != null && scene.anyShapeNear(minX, minY, maxX, maxY))
                || (zoned && friction.mayChangeWithin(minX, minY, maxX, maxY))
                || (forces != null && forces.mayChangeWithin(minX, minY, maxX, maxY))
                || (teleporter != null && teleporter.near(minX, minY, maxX, maxY));
    }

    /**
     * Whether a long step, integrated into the trial, keeps clear of what a step's end alone would
     * not show: water or the bounds touched by its stages between its ends, an element its stages
     * came near (they may stray a little outside the reach longestStep looked at), and ground
     * curving away fast enough to come within a quarter of the take-off threshold.
     */
    private boolean clearOfHazards(double tau) {
        RollingStep r = rolling;
        hazardVeto = r.stageLowest < 0 || !locate.inPlay(r.stageMinX, r.stageMinY) || !locate.inPlay(r.stageMaxX, r.stageMaxY);
        if (hazardVeto) return false;
        // The step's path, the cubic through its ends (as swept against obstacles), lies within
        // (4/27)(|v0 tau - c| + |v1 tau - c|) of its chord c; its stages too are looked at, and a
        // margin covers the cubic's own distance from the path.
        BallState b = ball;
        double cx = r.nx - b.x, cy = r.ny - b.y;
        double e0x = b.vx * tau - cx, e0y = b.vy * tau - cy, e1x = r.nvx * tau - cx, e1y = r.nvy * tau - cy;
        double bend = 4.0 / 27 * (Math.sqrt(e0x * e0x + e0y * e0y) + Math.sqrt(e1x * e1x + e1y * e1y)) + PATH_MARGIN;
        double minX = Math.min(Math.min(b.x, r.nx) - bend, r.stageMinX), maxX = Math.max(Math.max(b.x, r.nx) + bend, r.stageMaxX);
        double minY = Math.min(Math.min(b.y, r.ny) - bend, r.stageMinY), maxY = Math.max(Math.max(b.y, r.ny) + bend, r.stageMaxY);
        // Inside the box longestStep found clear nothing is near (the answers are monotone in the box).
        boolean inClearBox = minX >= clearMinX && minY >= clearMinY && maxX <= clearMaxX && maxY <= clearMaxY;
        if (!inClearBox && (elementNear(minX, minY, maxX, maxY) || (captureRule && hole.near(minX, minY, maxX, maxY)))) {
            return false;
        }
        if (shallowStep) {
            // Still braking, short of its stop by at least half the dt of speed it was left with.
            double braking = gravity * (Math.sqrt(r.stageSteepest) + b.muK);
            double endSpeed = Math.sqrt(r.nvx * r.nvx + r.nvy * r.nvy);
            if (!(r.stageSteepest < b.muK * b.muK && r.nvx * b.vx + r.nvy * b.vy > 0 && endSpeed > 0.5 * braking * dt)) return false;
        }
        return takeOff.gentleAlong(r.stageBend, tau) || !takeOff.near(b.x, b.y, b.vx, b.vy, b.h, b.hx, b.hy, tau);
    }

    /** Whether the last long step clearOfHazards refused had a stage in water or out of the bounds. */
    private boolean hazardVeto;

    /**
     * The length of a step that ends short of where the last long step (of length tau) met water
     * or the bounds: its stages, in the order of their times, by how far each is above the water
     * and inside the bounds, interpolated between the last one clear and the first one not; less
     * {@link #SHORE_MARGIN} dt, so that the next steps, of dt, meet it. A guess: the step is
     * checked as any long step.
     */
    private double shoreLength(double tau) {
        RollingStep r = rolling;
        BallState b = ball;
        double before = 0, clear = Math.min(b.h, locate.depthInside(b.x, b.y));
        for (int k = 0; k < RollingStep.STAGE_TIMES.length; k++) {
            double at = RollingStep.STAGE_TIMES[k];
            double depth = Math.min(r.stageH[k], locate.depthInside(r.stageX[k], r.stageY[k]));
            if (!(depth >= 0)) {
                double crossing = clear > 0 && depth < 0 ? before + (at - before) * clear / (clear - depth) : before;
                return crossing * tau - SHORE_MARGIN * dt;
            }
            before = at;
            clear = depth;
        }
        return 0;
    }

    /** How far (in dt) short of the crossing its stages suggest a step towards water or the bounds ends. */
    static final double SHORE_MARGIN = 0.5;

    /** Completes a step of length tau of the given kind, with events, and commits it. */
    private void finishStep(double tau, RollingStep.Kind kind, double a1x, double a1y, double speed0) {
        try {
            // A long step has kept clear of every zone's edge (clearOfHazards): only a step of at
            // most dt may end in another zone.
            if (zoned && kind == RollingStep.Kind.INTEGRATOR && !(controlled && control.isLong(tau))) {
                tau = locate.zoneEdge(tau, a1x, a1y);
            }
            commitStep(tau, kind, a1x, a1y, speed0);
        } finally {
            rolling.frozenMuK = Double.NaN;
            rolling.pushFrozen = false;
            rolling.uniformForce = false;
        }
    }

    private void commitStep(double tau, RollingStep.Kind kind, double a1x, double a1y, double speed0) {
        BallState b = ball;
        RollingTrial tr = trial;
        // On smooth ground a step whose stages saw the ground bend away gently stays on it (TakeOff.staysDown).
        boolean staysDown = smooth && tr.holds(tau) && takeOff.staysDown(tr.heldBend, tau);
        if (kind == RollingStep.Kind.INTEGRATOR && !staysDown && takesOffWithin(tau, a1x, a1y)) {
            // The ground falls away faster than gravity can pull the ball down: it flies this step,
            // from where the ground begins to curve away too fast (found by bisection). Decided
            // before water and the bounds, which a flying ball only meets where it comes down.
            launchWithin(tau, a1x, a1y);
            return;
        }
        if (!(tr.holds(tau) && kind == RollingStep.Kind.INTEGRATOR)) tr.run(tau, kind, a1x, a1y);
        if (!Double.isFinite(tr.nx + tr.ny + tr.nvx + tr.nvy)) throw NonFiniteMotionException.motion(b.x, b.y);
        // A stop step ends at rest, and so does a slow step in which friction held the ball.
        boolean stopping = kind == RollingStep.Kind.STOP
                || (kind == RollingStep.Kind.SLOW && tr.nvx == 0 && tr.nvy == 0);
        double endTau = tau;
        Outcome event = locate.hazardAtEnd(tr.nx, tr.ny);
        if (event != null) {
            endTau = locate.hazard(tau, kind, a1x, a1y);
            event = locate.hazardAt(tr.nx, tr.ny);
        }
        boolean leaves = false;
        if (lean != null && lean.active() && !lean.touches(tr.nx, tr.ny)) {
            // Past the end of the obstacle it leans on: the step ends there, and it rolls on free.
            endTau = locate.obstacleEnd(lean, endTau, kind, a1x, a1y);
            tr.run(endTau, kind, a1x, a1y);
            stopping = false;
            event = null;
            leaves = true;
        }
        boolean collided = false;
        if (scene != null && paths.sweep(b.x, b.y, b.h + ballRadius, b.vx, b.vy, 0,
                tr.nx, tr.ny, 0, tr.nvx, tr.nvy, 0, endTau, true)) {
            // The ball reaches an obstacle first: the step ends there (on the swept path).
            endTau *= paths.contactAt;
            tr.run(endTau, kind, a1x, a1y);
            tr.nx = paths.contactX;
            tr.ny = paths.contactY;
            stopping = false;
            event = null;
            collided = true;
            leaves = false;
        }
        int teleport = -1;
        if (teleporter != null) {
            // The ball enters a teleport's entry before the step's end: the step ends there.
            double entry = teleporter.locate(endTau, kind, a1x, a1y);
            if (entry >= 0) {
                endTau = entry;
                teleport = teleporter.entered;
                stopping = false;
                event = null;
                collided = false;
                leaves = false;
            } else if (collided) {
                tr.nx = paths.contactX;
                tr.ny = paths.contactY;
            }
        }
        double speed1 = stopping && event == null ? 0 : Math.sqrt(tr.nvx * tr.nvx + tr.nvy * tr.nvy);
        boolean pathEndsHere = stopping || event != null || collided || teleport >= 0;
        if (captureRule && hole.captures(tr.nx, tr.ny, speed0, speed1, endTau, pathEndsHere)) {
            return;
        }
        b.markStepStart();
        b.x = tr.nx;
        b.y = tr.ny;
        b.vx = stopping && event == null ? 0 : tr.nvx;
        b.vy = stopping && event == null ? 0 : tr.nvy;
        b.t += endTau;
        b.steps++;
        b.pieceTime = endTau;
        if (endTau > dt * (1 + 1e-9)) reports.path(b.px, b.py, b.pvx, b.pvy, b.pt, b.x, b.y, tr.nvx, tr.nvy, b.t);
        if (event != null) {
            // In water the ball floats on its surface (z = 0), as a flying ball that lands there.
            double h = terrain.height(b.x, b.y);
            b.z = event == Outcome.WATER && h < 0 ? 0 : h;
            reports.state();
            reports.finish(event, b.x, b.y, b.z);
            return;
        }
        b.sampleGround();
        b.z = b.h;
        if (teleport >= 0) {
            if (lean != null) lean.release();
            rest.forget();
            reports.state();
            teleporter.send(teleport);
            reports.state();
            b.resume = true;
            return;
        }
        if (collided) {
            contact.whileRolling();
            reports.state();
            b.resume = true;
            return;
        }
        if (leaves) {
            lean.release();
            reports.state();
            b.resume = true;
            b.subPiece = true;
            return;
        }
        if (!stopping && !energy.dissipates(kind, a1x, a1y)) return;
        reports.state();
    }

    /** Whether the ball leaves the ground within the coming tau (docs/physics.md, "Taking off"). */
    private boolean takesOffWithin(double tau, double a1x, double a1y) {
        BallState b = ball;
        takeOff.from(b.x, b.y, b.vx, b.vy, b.h, b.hx, b.hy, b.muK, b.fx, b.fy);
        return takeOff.takesOff(tau, a1x, a1y);
    }

    /** Rolls until the moment of take-off within the coming tau, then launches the ball from there. */
    private void launchWithin(double tau, double a1x, double a1y) {
        BallState b = ball;
        double rolled = takeOff.time(tau, a1x, a1y);
        if (rolled > 0) {
            trial.run(rolled, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            b.x = trial.nx;
            b.y = trial.ny;
            b.vx = trial.nvx;
            b.vy = trial.nvy;
            b.t += rolled;
            b.sampleGround();
        }
        b.z = b.h;
        b.vz = b.hx * b.vx + b.hy * b.vy;
        b.flying = true;
        if (lean != null) lean.release();
        reports.event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
        b.pieceTime = rolled;
        b.resume = true;
    }
}
