package minigolf.physics;

import minigolf.collision.CollisionScene;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.terrain.Terrain;

/**
 * One stroke of the ball, advanced one fixed step at a time. The game calls {@link #step()} at
 * 60 Hz to animate it; bots and the command line run it to the end through {@link Simulator}:
 * both use exactly this code.
 *
 * <p>This class is the outline: a step is a series of pieces, each rolling ({@link RollingPhase})
 * or flying ({@link FlightPhase}), until the step's time is spent, the stroke ends, or the ball is
 * wedged. The state they share is a {@link BallState}; what the stroke tells the world goes
 * through {@link StrokeReports}. The pieces' parts: {@link RollingStep} and {@link FlightStep}
 * integrate, {@link RollingTrial} holds a rolling step until it is committed, {@link StepControl}
 * chooses its length, {@link StepLocator} finds hazards, zone edges and an obstacle's end inside
 * it, {@link RestRule} decides when the ball stops and whether it stays, {@link TakeOff} when it
 * leaves the ground, {@link PathSweep} where it meets an obstacle and {@link ObstacleContact} how
 * it answers, {@link Leaning} how it rolls along one, {@link GroundImpact} how it lands,
 * {@link HoleRules} when it drops, and {@link EnergyGuard} keeps a rolling step from gaining energy.
 *
 * <p>Obstacles and flight (docs/physics.md): the state is 3-D, (x, y, z) being the ball's contact
 * point. Each step's path is swept with the ball's sphere against the obstacles; at the first
 * contact the step is cut, the velocity reflected (normal part times the restitution, tangential
 * part kept) and the rest of the step integrated, up to {@link #MAX_PIECES} contacts per step. A
 * flying ball moves under gravity and quadratic drag (always RK4) until it lands, bounces or
 * settles back into rolling.
 */
public final class Stroke {
    /** Most contacts, launches and landings handled within one step; a ball wedged harder than that stops. */
    static final int MAX_PIECES = 16;
    /** A ball leaving a surface lower than this (m) stays on it: it hops slower than sqrt(2 g HOP_HEIGHT). */
    static final double HOP_HEIGHT = 0.001;

    private final double dt;
    private final double maxTime;
    private final double maxSpeed;
    /** The course's {@code puttsOnly}: a shot's upward part is dropped, the ball struck along the ground. */
    private final boolean puttsOnly;
    private final PlayArea area;
    private final PathSweep paths;
    /** The course clock when the ball was hit (s). */
    private double startClock;
    private final BallState ball;
    private final StrokeReports reports;
    private final RollingStep steps;
    private final StepControl control;
    private final RollingTrial trial;
    private final RestRule rest;
    private final RollingPhase rolling;
    private final FlightPhase flight;
    /** The ball at frame times, for the game; the reports held back until the frames reach them. */
    private final FrameView view;
    private FrameDelay delay;
    /** Whether the stroke is driven frame by frame ({@link #step()}): the game's strokes. */
    private boolean framed;
    private long frames;
    private boolean shownEnd;
    /** The bricks' hits this stroke (null without bricks) and the state they start from: the world's. */
    private final BrickHits bricks;
    private final CourseState startState;
    /** Whether a {@link Simulator} is running this stroke now (it reuses one per course). */
    boolean running;

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
        this(world, settings, x0, y0, vx0, vy0, vz0, 0, listener, recordEvents);
    }

    /**
     * As {@link #Stroke(World, SimulationSettings, double, double, double, double, double,
     * TrajectoryListener, boolean)}, played at course clock {@code clock} (s): the moment the
     * moving obstacles are at when the ball is hit (docs/course-format.md, "Moving obstacles");
     * {@link #clock()} is the course clock as the stroke goes on.
     */
    public Stroke(World world, SimulationSettings settings, double x0, double y0, double vx0, double vy0, double vz0,
                  double clock, TrajectoryListener listener, boolean recordEvents) {
        this(world, settings);
        start(x0, y0, vx0, vy0, vz0, clock, listener, recordEvents, true);
    }

    /**
     * The parts of a stroke on this course, built once: {@link Simulator} keeps one and
     * {@link #start starts} it again for every shot, so a shot allocates nothing to set up.
     */
    Stroke(World world, SimulationSettings settings) {
        PhysicsSettings physics = world.physics();
        Terrain terrain = world.terrain();
        FrictionField friction = world.friction();
        PlayArea area = world.playArea();
        Solids scene = Solids.of(world);
        double gravity = physics.gravity();
        double hopSpeed = Math.sqrt(2 * gravity * HOP_HEIGHT);
        double ballRadius = physics.ballRadius();
        boolean complete = physics.model() == PhysicsModel.COMPLETE;
        this.dt = settings.dt();
        this.maxTime = settings.maxTime();
        this.maxSpeed = physics.maxSpeed();
        this.puttsOnly = physics.puttsOnly();
        this.area = area;
        GroundCache ground = new GroundCache(terrain);
        ForceField forces = world.forces();
        this.ball = new BallState(ground, friction, forces, gravity, complete);
        this.reports = new StrokeReports(ball, terrain, dt);
        this.view = new FrameView(terrain);

        RollingStep steps = new RollingStep(terrain, friction, forces, gravity, complete, settings.integrator(), dt);
        steps.share(ground);
        StepControl control = settings.integrator() == Integrator.RK4 ? new StepControl(steps, dt) : null;
        RollingTrial trial = new RollingTrial(ball, steps, control);
        RestRule rest = new RestRule(world, scene);
        PathSweep paths = new PathSweep(scene, terrain, ballRadius, ball);
        this.paths = paths;
        Leaning lean = scene == null ? null : new Leaning(scene, terrain, steps, ballRadius, gravity, complete);
        HoleRules hole = new HoleRules(ball, reports, terrain, world.holes());
        this.bricks = scene == null ? null : scene.brickHits;
        this.startState = world.state();
        ObstacleContact contact = new ObstacleContact(ball, reports, paths.hit, rest, lean, hopSpeed, physics.maxSpeed(),
                gravity, bricks);
        this.steps = steps;
        this.control = control;
        this.trial = trial;
        this.rest = rest;
        StepLocator locator = new StepLocator(ball, trial, steps, terrain, ground, friction, forces, area);
        if (control != null && (friction.hasZones() || (forces != null && forces.hasPushZones()))) control.edges = locator;
        // The closed-form stopping tail: the classic model's, on smooth ground, with the error control.
        StoppingTail tail = control != null && !complete && terrain.isSmooth() && !area.hasDeletedCells()
                ? new StoppingTail(ball, ground, terrain, locator, reports, rest, gravity, dt, settings.maxTime()) : null;
        this.rolling = new RollingPhase(ball, reports, steps, trial, control, locator, rest,
                new TakeOff(terrain, steps, gravity), hole, new EnergyGuard(ball, trial, reports, terrain, gravity, complete, forces),
                scene, lean, paths, contact, terrain, friction, forces,
                world.teleports() == null ? null : new Teleporter(world.teleports(), ball, trial, reports), area, tail, gravity,
                ballRadius, dt, settings.maxTime());
        this.flight = new FlightPhase(ball, reports, new FlightStep(terrain, gravity, physics.dragFactor()),
                new GroundImpact(physics.groundRestitution(), hopSpeed), hole, rest, area, scene, paths, contact,
                ballRadius, dt, settings.maxTime());
    }

    /**
     * (Re)starts the stroke from (x0, y0) on the ground with velocity (vx0, vy0, vz0), as the
     * constructor describes: every part forgets the last shot. A stroke {@code framed} is driven
     * frame by frame ({@link #step()}): it shows the ball at frame times and holds the listener's
     * reports back until the frames reach them; otherwise the listener hears them as they come.
     *
     * @throws IllegalArgumentException if the shot is faster than the course's maxSpeed
     */
    void start(double x0, double y0, double vx0, double vy0, double vz0, double clock, TrajectoryListener listener,
               boolean recordEvents, boolean framed) {
        double speed = Math.sqrt(vx0 * vx0 + vy0 * vy0 + vz0 * vz0);
        if (!Double.isFinite(speed)) {
            throw new IllegalArgumentException("shot velocity must be finite numbers");
        }
        if (speed > maxSpeed * (1 + 1e-12)) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "shot speed %.3f m/s exceeds the course's maxSpeed of %s m/s", speed, maxSpeed));
        }
        if (!Double.isFinite(clock)) throw new IllegalArgumentException("the course clock must be a finite number");
        if (puttsOnly) vz0 = 0;
        startClock = clock;
        BallState ball = this.ball;
        ball.reset(x0, y0, vx0, vy0);
        paths.start(clock);
        rolling.start(clock, shotKey(x0, y0, vx0, vy0, vz0, clock));
        this.framed = framed;
        frames = 0;
        shownEnd = false;
        delay = framed && listener != null ? new FrameDelay(listener) : null;
        reports.start(delay != null ? delay : listener, recordEvents);
        steps.reset();
        if (control != null) control.reset();
        trial.reset();
        rest.forget();
        if (bricks != null) bricks.start(startState);

        ball.sampleGround();
        ball.z = ball.h;
        ball.startZ = ball.h;
        if (!area.contains(ball.x, ball.y)) {
            reports.finish(Outcome.OUT, ball.x, ball.y, ball.z);
        } else if (ball.h < 0 || ball.entersHazard()) {
            reports.finish(Outcome.WATER, ball.x, ball.y, ball.z);
        } else if (vz0 > 0 && vz0 > ball.hx * vx0 + ball.hy * vy0) {
            ball.flying = true;
            ball.vz = vz0;
            reports.event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
        }
        view.start(ball);
        if (ball.outcome != null) {
            showEnd();
        } else if (delay != null) {
            delay.release(0);
        }
    }

    /**
     * Whether the stroke has ended: for a stroke driven frame by frame, once the frames have
     * reached its end (the integration may have got there a step earlier).
     */
    public boolean isFinished() {
        return ball.outcome != null && (!framed || shownEnd);
    }

    /** The result; only valid once {@link #isFinished()}. */
    public ShotResult result() {
        if (!isFinished()) throw new IllegalStateException("the stroke has not finished");
        return new ShotResult(ball.outcome, ball.endX, ball.endY, ball.t, ball.steps, ball.endZ, reports.events(),
                bricks == null ? startState : bricks.state());
    }

    /** The course as the stroke has left it so far (the bricks standing): the world's state until a brick breaks. */
    public CourseState state() {
        return bricks == null ? startState : bricks.state();
    }

    // The ball at the last frame shown (after run(): at its end).
    public double x() { return view.x; }
    public double y() { return view.y; }
    public double vx() { return view.vx; }
    public double vy() { return view.vy; }
    /** Height of the ball's contact point (its lowest point): the terrain height while it rolls. */
    public double z() { return view.z; }
    /** Vertical velocity: in flight its own, while rolling the rate at which the ground under it rises. */
    public double vz() { return view.vz; }
    public boolean isFlying() { return view.flying; }
    public double time() { return view.t; }
    /** The course clock at the last frame shown: the clock when the ball was hit plus {@link #time()}. */
    public double clock() { return startClock + view.t; }
    /** Integration steps taken so far (they need not end on frames). */
    public int steps() { return ball.steps; }

    /**
     * Advances the stroke by one frame of dt: the integrator takes its steps until it has passed
     * the frame's time, and the ball is shown there ({@link FrameView}). Does nothing once finished.
     */
    public void step() {
        if (isFinished()) return;
        BallState b = ball;
        double target = ++frames * dt;
        while (b.outcome == null && b.t < target) advance();
        // An end a rounding error past the frame's time (frames * dt against summed steps) is shown there.
        if (b.outcome != null && b.t <= target + 1e-9 * dt) {
            showEnd();
        } else {
            view.show(target, b);
            if (delay != null) delay.release(target);
        }
    }

    /** One integration step of the length the integrator chooses, as a series of pieces. */
    private void advance() {
        BallState b = ball;
        double remaining = b.flying || control == null ? dt : control.allowed();
        int pieces = 0;
        b.movingContact = false;
        while (pieces < MAX_PIECES) {
            b.resume = false;
            b.subPiece = false;
            if (framed) view.mark(b);
            remaining -= b.flying ? flight.piece(remaining) : rolling.piece(remaining);
            // The pieces stop at the time limit: the stroke ends there, not a step later.
            if (b.outcome == null && b.t >= maxTime) reports.finish(Outcome.TIMEOUT, b.x, b.y, b.z);
            if (!b.resume || b.outcome != null || remaining <= 1e-9 * dt) return;
            // A sub-step the error control asked for is no contact: it does not count towards a wedge.
            if (!b.subPiece) pieces++;
        }
        // Wedged: more contacts in one step than we follow. Crushed by a moving obstacle (against
        // another, or the ground), the ball is out of play; otherwise it stops where it is for the
        // rest of the step.
        if (b.movingContact) {
            reports.removedFromPlay();
            return;
        }
        b.vx = 0;
        b.vy = 0;
        b.vz = 0;
        if (framed) view.mark(b);
        b.t += remaining;
    }

    private void showEnd() {
        shownEnd = true;
        view.end(ball);
        if (delay != null) delay.release(Double.POSITIVE_INFINITY);
    }

    /**
     * Ends the stroke as out of play where the ball is: for the game, when a step has thrown
     * {@link NonFiniteMotionException} (the ball reached terrain that is not finite), so the
     * player gets the ball back with a penalty instead of a crash.
     */
    public void endOutOfPlay() {
        if (ball.outcome == null) reports.finish(Outcome.OUT, ball.x, ball.y, ball.z);
        showEnd();
    }

    /** Runs the stroke to its end. */
    public ShotResult run() {
        BallState b = ball;
        while (b.outcome == null) advance();
        showEnd();
        return result();
    }

    /**
     * Runs the stroke to its end as the game rules it: a stroke whose motion stops being finite
     * (a terrain not finite somewhere between the loader's samples) ends out of play there.
     */
    public ShotResult runOrEndOutOfPlay() {
        try {
            return run();
        } catch (NonFiniteMotionException e) {
            endOutOfPlay();
            return result();
        }
    }

    /** The shot as one number (its bits mixed), for the teleports that draw their exits: the same shot, the same draws. */
    static long shotKey(double x0, double y0, double vx0, double vy0, double vz0, double clock) {
        long k = Double.doubleToLongBits(x0 + 0.0);
        k = 31 * k + Double.doubleToLongBits(y0 + 0.0);
        k = 31 * k + Double.doubleToLongBits(vx0 + 0.0);
        k = 31 * k + Double.doubleToLongBits(vy0 + 0.0);
        k = 31 * k + Double.doubleToLongBits(vz0 + 0.0);
        return 31 * k + Double.doubleToLongBits(clock + 0.0);
    }
}
