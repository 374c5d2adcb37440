package minigolf.physics;

import java.util.List;
import minigolf.collision.CollisionScene;
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
 * <p>The pieces: {@link RollingStep} integrates the rolling equations (Euler, RK2, RK4, the
 * analytic stop, the slow implicit step), {@link FlightStep} a flying ball, {@link RestRule}
 * decides when the ball stops and whether it stays, {@link TakeOff} when it leaves the ground,
 * {@link PathSweep} where it meets an obstacle, {@link EventLog} keeps the events. This class owns
 * the state and strings them together: hazards (water, bounds) located inside a step by bisection,
 * zone edges, the hole rules, contact responses, launch and landing, and the rule that no rolling
 * step gains energy.
 *
 * <p>Obstacles and flight (docs/physics.md): the state is 3-D, (x, y, z) being the ball's contact
 * point. Each step's path (a chord from start to end) is swept with the ball's sphere against the
 * obstacles; at the first contact the step is cut, the velocity reflected (normal part times the
 * restitution, tangential part kept) and the rest of the step integrated, up to
 * {@link #MAX_PIECES} contacts per step. A flying ball moves under gravity and quadratic drag
 * (always RK4) until it lands, bounces or settles back into rolling.
 */
public final class Stroke {
    /** Bisection halvings when locating an event inside a step: dt / 2^50 is far below 1 mm. */
    private static final int LOCATE_ITERATIONS = 50;
    /** Most contacts, launches and landings handled within one step; a ball wedged harder than that stops. */
    static final int MAX_PIECES = 16;
    /** A ball leaving a surface lower than this (m) stays on it: it hops slower than sqrt(2 g HOP_HEIGHT). */
    static final double HOP_HEIGHT = 0.001;

    private final Terrain terrain;
    private final FrictionField friction;
    private final PlayArea area;
    private final double gravity;
    /** A hop under HOP_HEIGHT with this course's gravity. */
    private final double hopSpeed;
    private final boolean complete;
    private final RollingStep rolling;
    private final FlightStep flight;
    private final RestRule rest;
    private final double dt;
    private final double maxTime;
    private final double holeX;
    private final double holeY;
    private final double holeRadius;
    private final boolean captureRule;
    private final double captureSpeed;
    private final TrajectoryListener listener;
    private final boolean zoned;
    private final CollisionScene scene;
    private final double ballRadius;
    private final GroundImpact impact;
    private final EventLog events;
    private final PathSweep paths;
    private final TakeOff takeOff;
    /** A ball settled against an obstacle rolls along it; null without obstacles. */
    private final Leaning lean;

    // The ball's state and the terrain sample at it (reused as the first stage of the next step).
    private double x, y, vx, vy, t;
    private double h, hx, hy, muK;
    private int steps;
    // The third dimension: z is the contact point's height (h while rolling), vz its rate of change.
    private double z, vz;
    private boolean flying;
    /** Set by a piece of a step (a contact, a launch, a landing) when the rest of the step is to be integrated. */
    private boolean resume;
    private double pieceTime;
    // The state at the start of the last rolling step, for a take-off found at its end.
    private double px, py, pvx, pvy, pt, ph, phx, phy, pMuK;
    private int pSteps;

    /** The RK4 step's error control; null for the other integrators. */
    private final StepControl control;
    // Whether n* holds the controlled step of length trialTau, and whether this piece was one it shortened.
    private boolean trialHeld, subPiece;
    private double trialTau;

    private Outcome outcome;
    private double endX, endY, endZ;
    // Flight scratch: the state a flight sub-step produced.
    private double fx, fy, fz, fvx, fvy, fvz;

    // Scratch: the terrain sample and the state a sub-step produced.
    private final double[] sample = new double[3];
    private double nx, ny, nvx, nvy;

    /**
     * Starts a stroke from (x0, y0) with velocity (vx0, vy0).
     *
     * @throws IllegalArgumentException if the shot is faster than the course's maxSpeed
     */
    public Stroke(World world, SimulationSettings settings, double x0, double y0, double vx0, double vy0,
                  TrajectoryListener listener) {
        this(world, settings, x0, y0, vx0, vy0, 0, listener, false);
    }

    /**
     * Starts a stroke from (x0, y0) on the ground with velocity (vx0, vy0, vz0). The ball flies if
     * vz0 &gt; 0 and it rises faster than the ground does along (vx0, vy0); otherwise it rolls with
     * (vx0, vy0). The speed limit applies to the whole vector. Events are recorded (for
     * {@link ShotResult#events()}) only if {@code recordEvents}; the listener receives them anyway.
     *
     * @throws IllegalArgumentException if the shot is faster than the course's maxSpeed
     */
    public Stroke(World world, SimulationSettings settings, double x0, double y0, double vx0, double vy0, double vz0,
                  TrajectoryListener listener, boolean recordEvents) {
        PhysicsSettings physics = world.physics();
        double speed = Math.sqrt(vx0 * vx0 + vy0 * vy0 + vz0 * vz0);
        if (!Double.isFinite(speed)) {
            throw new IllegalArgumentException("shot velocity must be finite numbers");
        }
        if (speed > physics.maxSpeed() * (1 + 1e-12)) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "shot speed %.3f m/s exceeds the course's maxSpeed of %s m/s", speed, physics.maxSpeed()));
        }
        this.terrain = world.terrain();
        this.friction = world.friction();
        this.area = world.playArea();
        this.gravity = physics.gravity();
        this.hopSpeed = Math.sqrt(2 * gravity * HOP_HEIGHT);
        this.complete = physics.model() == PhysicsModel.COMPLETE;
        this.rolling = new RollingStep(terrain, friction, gravity, complete, settings.integrator());
        this.flight = new FlightStep(terrain, gravity, physics.dragFactor());
        this.rest = new RestRule(world);
        this.paths = new PathSweep(world.obstacles(), terrain, physics.ballRadius());
        this.takeOff = new TakeOff(terrain, rolling, gravity);
        this.dt = settings.dt();
        this.control = settings.integrator() == Integrator.RK4 ? new StepControl(rolling, dt) : null;
        this.maxTime = settings.maxTime();
        Hole hole = world.hole();
        this.holeX = hole.position().x();
        this.holeY = hole.position().y();
        this.holeRadius = hole.radius();
        this.captureRule = hole.rule() == HoleRule.CAPTURE;
        this.captureSpeed = hole.effectiveCaptureSpeed();
        this.listener = listener;
        this.zoned = friction.hasZones();
        this.scene = world.obstacles();
        this.ballRadius = physics.ballRadius();
        this.impact = new GroundImpact(physics.groundRestitution(), hopSpeed);
        this.lean = scene == null ? null
                : new Leaning(scene, terrain, rolling, ballRadius, gravity, complete);
        this.events = recordEvents ? new EventLog() : null;
        this.x = x0;
        this.y = y0;
        this.vx = vx0;
        this.vy = vy0;
        sampleCurrent();
        this.z = h;
        if (!area.contains(x, y)) {
            finish(Outcome.OUT, x, y, z);
        } else if (h < 0) {
            finish(Outcome.WATER, x, y, z);
        } else if (vz0 > 0 && vz0 > hx * vx0 + hy * vy0) {
            flying = true;
            vz = vz0;
            event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
        }
    }

    public boolean isFinished() {
        return outcome != null;
    }

    /** The result; only valid once {@link #isFinished()}. */
    public ShotResult result() {
        if (outcome == null) throw new IllegalStateException("the stroke has not finished");
        return new ShotResult(outcome, endX, endY, t, steps, endZ, events == null ? List.of() : events.list());
    }

    public double x() { return x; }
    public double y() { return y; }
    public double vx() { return vx; }
    public double vy() { return vy; }
    /** Height of the ball's contact point (its lowest point): the terrain height while it rolls. */
    public double z() { return z; }
    /** Vertical velocity: in flight its own, while rolling the rate at which the ground under it rises. */
    public double vz() { return flying ? vz : hx * vx + hy * vy; }
    public boolean isFlying() { return flying; }
    public double time() { return t; }
    public int steps() { return steps; }
    /** The terrain height under the ball. */
    public double height() { return h; }

    /** Advances the ball by one step (or ends the stroke). Does nothing once finished. */
    public void step() {
        if (outcome != null) return;
        double remaining = dt;
        int pieces = 0;
        while (pieces < MAX_PIECES) {
            resume = false;
            subPiece = false;
            remaining -= flying ? flightPiece(remaining) : rollingPiece(remaining);
            if (!resume || outcome != null || remaining <= 1e-9 * dt) return;
            // A sub-step the error control asked for is no contact: it does not count towards a wedge.
            if (!subPiece) pieces++;
        }
        // Wedged: more contacts in one step than we follow. The ball stops where it is for the rest of it.
        t += remaining;
        vx = 0;
        vy = 0;
        vz = 0;
    }

    /** One rolling piece of at most tau seconds; returns the time it took. */
    private double rollingPiece(double tau) {
        if (t >= maxTime) {
            finish(Outcome.TIMEOUT, x, y, z);
            return 0;
        }
        double speed = Math.sqrt(vx * vx + vy * vy);
        // A ball leaning on an obstacle leaves it at rest, where the ground no longer pulls it
        // towards it, or where the obstacle is out of reach (its end).
        boolean leaning = lean != null && lean.active();
        if (leaning && (speed == 0 || !lean.holds(x, y, hx, hy))) {
            lean.release();
            leaning = false;
        }
        // A ball the rest rule sends back down (it turned faster than REST_SPEED) is not at rest
        // when an energy cut leaves it at v = 0 at its turn: it starts down again, once.
        boolean sentBack = speed == 0 && rest.rollsBack();
        if (sentBack) rest.forget();
        if (speed == 0 && !sentBack && rest.holds(x, y, h, hx, hy, muK)) {
            finish(isInHole(x, y) ? Outcome.HOLED : Outcome.STOPPED, x, y, z);
            return 0;
        }
        pieceTime = tau;
        rolling.acceleration(hx, hy, muK, vx, vy);
        double a1x = rolling.ax, a1y = rolling.ay;
        if (speed > 0) {
            double decelerationAlongV = -(a1x * vx + a1y * vy) / speed;
            // Leaning, the rule sees the ground without the part of its slope the obstacle takes.
            double ghx = hx, ghy = hy;
            if (leaning) {
                lean.effective(hx, hy);
                ghx = lean.gx;
                ghy = lean.gy;
            }
            double slope = Math.sqrt(ghx * ghx + ghy * ghy);
            if (decelerationAlongV > 0) {
                double stop = rest.stopWithin(tau, speed, decelerationAlongV, slope, vx, vy, ghx, ghy, muK);
                if (stop >= 0) {
                    finishStep(stop, RollingStep.Kind.STOP, a1x, a1y, speed);
                    return pieceTime;
                }
            } else {
                rest.forget();
            }
            // A slow, braking ball: the friction direction would flip inside the integrator's
            // stages (they can cancel and make the ball creep for ever) and, explicit, it would
            // chatter sideways; gravity and friction change v by at most g (|grad h| + mu_k) dt
            // in a step. Such steps treat friction implicitly (see subStep).
            double maxChange = gravity * (slope + muK) * tau * (control != null ? StepControl.SLOW_FRACTION : 1);
            if (decelerationAlongV > 0 && speed <= maxChange) {
                finishStep(tau, RollingStep.Kind.SLOW, a1x, a1y, speed);
                return pieceTime;
            }
        }
        double whole = tau;
        if (control != null) tau = controlledLength(tau, a1x, a1y);
        pieceTime = tau;
        finishStep(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y, speed);
        if (tau < whole && !resume && outcome == null) {
            resume = true;
            subPiece = true;
        }
        return pieceTime;
    }

    /** The step control's length for the coming RK4 step (at most tau); n* then hold that step. */
    private double controlledLength(double tau, double a1x, double a1y) {
        rolling.from(x, y, vx, vy, hx, hy, muK);
        double h = control.length(tau, a1x, a1y);
        nx = rolling.nx;
        ny = rolling.ny;
        nvx = rolling.nvx;
        nvy = rolling.nvy;
        trialHeld = true;
        trialTau = h;
        return h;
    }

    /**
     * Ends the stroke as out of play where the ball is: for the game, when a step has thrown
     * {@link NonFiniteMotionException} (the ball reached terrain that is not finite), so the
     * player gets the ball back with a penalty instead of a crash.
     */
    public void endOutOfPlay() {
        if (outcome == null) finish(Outcome.OUT, x, y, z);
    }

    /** Runs the stroke to its end. */
    public ShotResult run() {
        while (outcome == null) step();
        return result();
    }

    private boolean isInHole(double px, double py) {
        double dx = px - holeX, dy = py - holeY;
        return dx * dx + dy * dy <= holeRadius * holeRadius;
    }

    /** Completes a step of length tau of the given kind, with events, and commits it. */
    private void finishStep(double tau, RollingStep.Kind kind, double a1x, double a1y, double speed0) {
        try {
            if (zoned && kind == RollingStep.Kind.INTEGRATOR) tau = stopAtZoneEdge(tau, a1x, a1y);
            commitStep(tau, kind, a1x, a1y, speed0);
        } finally {
            rolling.frozenMuK = Double.NaN;
        }
    }

    /**
     * Friction jumps at a zone's edge, and an integrator step across the jump loses its order.
     * If the step would end in another zone, it is shortened to end just past the edge, with the
     * friction of the zone it started in; the next step starts with the new zone's friction.
     */
    private double stopAtZoneEdge(double tau, double a1x, double a1y) {
        int zone = friction.zoneAt(x, y);
        if (!(trialHeld && tau == trialTau)) subStep(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
        if (friction.zoneAt(nx, ny) == zone) return tau;
        rolling.frozenMuK = muK;
        double inside = 0, beyond = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (inside + beyond);
            subStep(mid, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (friction.zoneAt(nx, ny) == zone) inside = mid; else beyond = mid;
        }
        return beyond;
    }

    private void commitStep(double tau, RollingStep.Kind kind, double a1x, double a1y, double speed0) {
        if (kind == RollingStep.Kind.INTEGRATOR && takesOffWithin(tau, a1x, a1y)) {
            // The ground falls away faster than gravity can pull the ball down: it flies this step,
            // from where the ground begins to curve away too fast (found by bisection). Decided
            // before water and the bounds, which a flying ball only meets where it comes down.
            launchWithin(tau, a1x, a1y);
            return;
        }
        if (!(trialHeld && tau == trialTau && kind == RollingStep.Kind.INTEGRATOR)) subStep(tau, kind, a1x, a1y);
        if (!Double.isFinite(nx + ny + nvx + nvy)) throw NonFiniteMotionException.motion(x, y);
        // A stop step ends at rest, and so does a slow step in which friction held the ball.
        boolean stopping = kind == RollingStep.Kind.STOP || (kind == RollingStep.Kind.SLOW && nvx == 0 && nvy == 0);
        double endTau = tau;
        Outcome event = hazardAt(nx, ny);
        if (event != null) {
            endTau = locateHazard(tau, kind, a1x, a1y);
            subStep(endTau, kind, a1x, a1y);
            event = hazardAt(nx, ny);
        }
        boolean leaves = false;
        if (lean != null && lean.active() && !lean.touches(nx, ny)) {
            // Past the end of the obstacle it leans on: the step ends there, and it rolls on free.
            endTau = locateObstacleEnd(endTau, kind, a1x, a1y);
            subStep(endTau, kind, a1x, a1y);
            stopping = false;
            event = null;
            leaves = true;
        }
        boolean collided = false;
        if (scene != null && paths.sweep(x, y, h + ballRadius, vx, vy, 0, nx, ny, 0, nvx, nvy, 0, endTau, true)) {
            // The ball reaches an obstacle first: the step ends there (on the swept path).
            endTau *= paths.contactAt;
            subStep(endTau, kind, a1x, a1y);
            nx = paths.contactX;
            ny = paths.contactY;
            stopping = false;
            event = null;
            collided = true;
            leaves = false;
        }
        double speed1 = stopping && event == null ? 0 : Math.sqrt(nvx * nvx + nvy * nvy);
        boolean pathEndsHere = stopping || event != null || collided;
        if (captureRule && captureOnSegment(nx, ny, speed0, speed1, endTau, pathEndsHere)) {
            return;
        }
        px = x;
        py = y;
        pvx = vx;
        pvy = vy;
        pt = t;
        ph = h;
        phx = hx;
        phy = hy;
        pMuK = muK;
        pSteps = steps;
        x = nx;
        y = ny;
        vx = stopping && event == null ? 0 : nvx;
        vy = stopping && event == null ? 0 : nvy;
        t += endTau;
        steps++;
        pieceTime = endTau;
        if (event != null) {
            z = terrain.height(x, y);
            notifyListener();
            finish(event, x, y, z);
            return;
        }
        sampleCurrent();
        z = h;
        if (collided) {
            bounceOffObstacleWhileRolling();
            notifyListener();
            resume = true;
            return;
        }
        if (leaves) {
            lean.release();
            notifyListener();
            resume = true;
            subPiece = true;
            return;
        }
        if (!stopping && !dissipates(kind, a1x, a1y)) return;
        notifyListener();
    }

    /** E = |v|^2/2 + g h per unit mass; the complete model counts the vertical speed grad h . v too. */
    private double energy(double ux, double uy, double height, double gx, double gy) {
        double along = complete ? gx * ux + gy * uy : 0;
        return 0.5 * (ux * ux + uy * uy + along * along) + gravity * height;
    }

    /** Half the least friction work over a chord of this length from the step's start. */
    private double halfFrictionWork(double chord) {
        double work = pMuK * gravity * chord;
        return 0.5 * (complete ? work / Math.sqrt(1 + phx * phx + phy * phy) : work);
    }

    /**
     * Energy never grows (docs/course-format.md, rule 3): the committed step must have lost at
     * least half the least friction work over its chord. Smooth ground never comes near that; a
     * step across a crease (a V-shaped valley's floor, a cone's tip), where the start's slope
     * pumps energy in, does. Then the speed is cut to what the energy allows, or, where even the
     * end's height is out of reach, the step is cut where the energy runs out and the ball is
     * momentarily at rest there. Returns false when it has rewritten the step (and notified).
     */
    private boolean dissipates(RollingStep.Kind kind, double a1x, double a1y) {
        double e0 = energy(pvx, pvy, ph, phx, phy);
        double allowed = e0 - halfFrictionWork(Math.hypot(x - px, y - py));
        double slack = 1e-9 * (Math.abs(e0) + 1);
        double e1 = energy(vx, vy, h, hx, hy);
        if (e1 <= allowed + slack) return true;
        double kinetic = e1 - gravity * h;
        double room = allowed - gravity * h;
        if (room > 0 && kinetic > 0) {
            double keep = Math.sqrt(room / kinetic);
            vx *= keep;
            vy *= keep;
            notifyListener();
            return false;
        }
        // The end is higher than the energy reaches: go back and stop where it runs out.
        double spent = pieceTime;
        x = px;
        y = py;
        vx = pvx;
        vy = pvy;
        h = ph;
        hx = phx;
        hy = phy;
        muK = pMuK;
        t = pt;
        double reach = 0, beyond = spent;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (reach + beyond);
            subStep(mid, kind, a1x, a1y);
            double need = gravity * terrain.height(nx, ny) + halfFrictionWork(Math.hypot(nx - x, ny - y));
            if (need <= e0) reach = mid; else beyond = mid;
        }
        subStep(reach, kind, a1x, a1y);
        x = nx;
        y = ny;
        vx = 0;
        vy = 0;
        t = pt + reach;
        pieceTime = reach;
        sampleCurrent();
        z = h;
        notifyListener();
        resume = reach < spent;
        return false;
    }

    /** Whether the ball leaves the ground within the coming tau (docs/physics.md, "Taking off"). */
    private boolean takesOffWithin(double tau, double a1x, double a1y) {
        takeOff.from(x, y, vx, vy, h, hx, hy, muK);
        return takeOff.takesOff(tau, a1x, a1y);
    }

    /** Rolls until the moment of take-off within the coming tau, then launches the ball from there. */
    private void launchWithin(double tau, double a1x, double a1y) {
        double rolled = takeOff.time(tau, a1x, a1y);
        if (rolled > 0) {
            subStep(rolled, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            x = nx;
            y = ny;
            vx = nvx;
            vy = nvy;
            t += rolled;
            sampleCurrent();
        }
        z = h;
        vz = hx * vx + hy * vy;
        flying = true;
        if (lean != null) lean.release();
        event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
        pieceTime = rolled;
        resume = true;
    }

    /**
     * A rolling ball at an obstacle: its velocity along the ground, (vx, vy, grad h . v), is
     * reflected about the contact normal. If it then leaves the ground faster than a 1 mm hop, it
     * flies; otherwise the part into or off the ground is dropped and it rolls on.
     */
    private void bounceOffObstacleWhileRolling() {
        // A new heading: the rest rule's decision about a turn ahead was for the old one.
        rest.forget();
        double wz = hx * vx + hy * vy;
        double before = Math.sqrt(vx * vx + vy * vy + wz * wz);
        double vn = vx * paths.hit.nx + vy * paths.hit.ny + wz * paths.hit.nz;
        if (vn < 0) {
            double j = (1 + paths.hit.restitution) * vn;
            vx -= j * paths.hit.nx;
            vy -= j * paths.hit.ny;
            wz -= j * paths.hit.nz;
        }
        double norm = Math.sqrt(1 + hx * hx + hy * hy);
        double away = (wz - hx * vx - hy * vy) / norm; // speed off the ground along its normal
        if (away > hopSpeed) {
            vz = wz;
            flying = true;
            lean.release();
            event(StrokeEvent.Type.COLLISION, before, Math.sqrt(vx * vx + vy * vy + wz * wz));
            event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
            return;
        }
        // Project onto the ground's tangent plane (the ground takes the normal part).
        double gx = -hx / norm, gy = -hy / norm, gz = 1 / norm;
        double into = vx * gx + vy * gy + wz * gz;
        vx -= into * gx;
        vy -= into * gy;
        if (lean.settles(paths.hit.nx, paths.hit.ny, paths.hit.nz, vx, vy, hx, hy)) {
            // It settles against the obstacle (docs/physics.md): it rolls along it from here.
            vx = lean.vx;
            vy = lean.vy;
            x += lean.dx;
            y += lean.dy;
            sampleCurrent();
            z = h;
        }
        wz = hx * vx + hy * vy;
        event(StrokeEvent.Type.COLLISION, before, Math.sqrt(vx * vx + vy * vy + wz * wz));
    }

    // ---- flight ----

    /** One flying piece of at most tau seconds; returns the time it took. */
    private double flightPiece(double tau) {
        if (t >= maxTime) {
            finish(Outcome.TIMEOUT, x, y, z);
            return 0;
        }
        flightSub(tau);
        if (!Double.isFinite(fx + fy + fz + fvx + fvy + fvz)) throw NonFiniteMotionException.motion(x, y);
        double endTau = tau;
        boolean lands = false;
        if (fz < flight.groundAt(fx, fy)) {
            flight.from(x, y, z, vx, vy, vz);
            endTau = flight.locateLanding(tau);
            flightSub(endTau);
            lands = true;
        }
        boolean collided = false;
        if (scene != null) {
            double r = ballRadius;
            if (paths.sweep(x, y, z + r, vx, vy, vz, fx, fy, fz + r, fvx, fvy, fvz, endTau, false)) {
                endTau *= paths.contactAt;
                flightSub(endTau);
                fx = paths.contactX;
                fy = paths.contactY;
                fz = paths.contactZ - r;
                lands = false;
                collided = true;
            }
        }
        x = fx;
        y = fy;
        z = fz;
        vx = fvx;
        vy = fvy;
        vz = fvz;
        t += endTau;
        steps++;
        if (collided) {
            bounceOffObstacleInFlight();
            resume = outcome == null;
        } else if (lands) {
            land();
        }
        if (outcome == null) notifyListener();
        return endTau;
    }

    private void bounceOffObstacleInFlight() {
        double before = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double vn = vx * paths.hit.nx + vy * paths.hit.ny + vz * paths.hit.nz;
        if (vn < 0) {
            double j = (1 + paths.hit.restitution) * vn;
            vx -= j * paths.hit.nx;
            vy -= j * paths.hit.ny;
            vz -= j * paths.hit.nz;
        }
        double after = Math.sqrt(vx * vx + vy * vy + vz * vz);
        event(StrokeEvent.Type.COLLISION, before, after);
        // Settling on top of an obstacle (docs/physics.md, "Flight"): off a face turned upwards the
        // ball leaves slower than a 1 mm hop, whatever its speed along the face. It cannot roll
        // there, so it is unplayable: out, at the contact.
        double away = vn < 0 ? -vn * paths.hit.restitution : vn;
        if (paths.hit.nz > 0.5 && away < hopSpeed) {
            finish(Outcome.OUT, x, y, z);
        }
    }

    /**
     * The ball reaches the ground. Water or outside the bounds ends the stroke; inside the hole's
     * radius at a horizontal speed below v_c (1 - (delta/r)^2) it drops. Otherwise it bounces or
     * settles into rolling ({@link GroundImpact}).
     */
    private void land() {
        if (!area.contains(x, y)) {
            finish(Outcome.OUT, x, y, z);
            return;
        }
        sampleCurrent();
        if (h < 0) {
            z = 0;
            finish(Outcome.WATER, x, y, z);
            return;
        }
        z = h;
        double horizontal = Math.sqrt(vx * vx + vy * vy);
        double delta = Math.hypot(x - holeX, y - holeY);
        if (delta <= holeRadius) {
            double ratio = delta / holeRadius;
            if (horizontal < captureSpeed * (1 - ratio * ratio)) {
                finish(Outcome.HOLED, x, y, z);
                return;
            }
        }
        impact.impact(vx, vy, vz, hx, hy);
        vx = impact.vx;
        vy = impact.vy;
        vz = impact.vz;
        if (impact.settles) {
            flying = false;
            rest.forget();
            event(StrokeEvent.Type.LAND, impact.before, impact.after);
        } else {
            event(StrokeEvent.Type.BOUNCE, impact.before, impact.after);
        }
        resume = true;
    }

    /** A flight sub-step of length tau from the current state into f*. */
    private void flightSub(double tau) {
        flight.from(x, y, z, vx, vy, vz);
        flight.advance(tau);
        fx = flight.fx;
        fy = flight.fy;
        fz = flight.fz;
        fvx = flight.fvx;
        fvy = flight.fvy;
        fvz = flight.fvz;
    }

    private void notifyListener() {
        if (listener != null) listener.onState(t, x, y, z, vx, vy, vz());
    }

    private void event(StrokeEvent.Type type, double speedBefore, double speedAfter) {
        if (events == null && listener == null) return;
        StrokeEvent e = new StrokeEvent(t, type, x, y, z, speedBefore, speedAfter);
        if (events != null) events.add(e);
        if (listener != null) listener.onEvent(e);
    }


    /** Writes the state after a sub-step of length tau from the current state into n*. */
    private void subStep(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        trialHeld = false;
        rolling.from(x, y, vx, vy, hx, hy, muK);
        rolling.advance(tau, kind, a1x, a1y);
        nx = rolling.nx;
        ny = rolling.ny;
        nvx = rolling.nvx;
        nvy = rolling.nvy;
    }

    private Outcome hazardAt(double px, double py) {
        if (!area.contains(px, py)) return Outcome.OUT;
        if (terrain.height(px, py) < 0) return Outcome.WATER;
        return null;
    }

    /** The first sub-step length at which the obstacle the ball leans on is out of its reach, by bisection. */
    private double locateObstacleEnd(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        double on = 0, off = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (on + off);
            subStep(mid, kind, a1x, a1y);
            if (lean.touches(nx, ny)) on = mid; else off = mid;
        }
        return off;
    }

    /** The first sub-step length at which the ball is in a hazard, found by bisection. */
    private double locateHazard(double tau, RollingStep.Kind kind, double a1x, double a1y) {
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
        pieceTime = f * tau;
        z = terrain.height(cx, cy);
        vx = 0;
        vy = 0;
        if (listener != null) listener.onState(t, x, y, z, 0, 0, 0);
        finish(Outcome.HOLED, cx, cy, z);
        return true;
    }

    private void finish(Outcome result, double ex, double ey, double ez) {
        outcome = result;
        endX = ex;
        endY = ey;
        endZ = ez;
        vx = 0;
        vy = 0;
        vz = 0;
        flying = false;
        StrokeEvent.Type type = switch (result) {
            case HOLED -> StrokeEvent.Type.HOLED;
            case STOPPED -> StrokeEvent.Type.STOP;
            case WATER -> StrokeEvent.Type.WATER;
            case OUT -> StrokeEvent.Type.OUT;
            case TIMEOUT -> null;
        };
        if (type != null) event(type, Double.NaN, Double.NaN);
    }

    private void sampleCurrent() {
        terrain.sample(x, y, sample);
        h = sample[0];
        hx = sample[1];
        hy = sample[2];
        if (!Double.isFinite(h + hx + hy)) throw NonFiniteMotionException.terrain(x, y);
        muK = friction.kinetic(x, y);
    }

}
