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
    private final BallState ball;
    private final StrokeReports reports;
    private final RollingPhase rolling;
    private final FlightPhase flight;

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
        Terrain terrain = world.terrain();
        FrictionField friction = world.friction();
        PlayArea area = world.playArea();
        CollisionScene scene = world.obstacles();
        double gravity = physics.gravity();
        double hopSpeed = Math.sqrt(2 * gravity * HOP_HEIGHT);
        double ballRadius = physics.ballRadius();
        boolean complete = physics.model() == PhysicsModel.COMPLETE;
        this.dt = settings.dt();
        this.ball = new BallState(terrain, friction, x0, y0, vx0, vy0);
        this.reports = new StrokeReports(ball, listener, recordEvents);

        RollingStep steps = new RollingStep(terrain, friction, gravity, complete, settings.integrator());
        StepControl control = settings.integrator() == Integrator.RK4 ? new StepControl(steps, dt) : null;
        RollingTrial trial = new RollingTrial(ball, steps, control);
        RestRule rest = new RestRule(world);
        PathSweep paths = new PathSweep(scene, terrain, ballRadius);
        Leaning lean = scene == null ? null : new Leaning(scene, terrain, steps, ballRadius, gravity, complete);
        HoleRules hole = new HoleRules(ball, reports, terrain, world.hole());
        ObstacleContact contact = new ObstacleContact(ball, reports, paths.hit, rest, lean, hopSpeed);
        this.rolling = new RollingPhase(ball, reports, steps, trial,
                new StepLocator(ball, trial, steps, terrain, friction, area), rest, new TakeOff(terrain, steps, gravity),
                hole, new EnergyGuard(ball, trial, reports, terrain, gravity, complete), scene, lean, paths, contact,
                terrain, gravity, ballRadius, settings.maxTime(), friction.hasZones());
        this.flight = new FlightPhase(ball, reports, new FlightStep(terrain, gravity, physics.dragFactor()),
                new GroundImpact(physics.groundRestitution(), hopSpeed), hole, rest, area, scene, paths, contact,
                ballRadius, settings.maxTime());

        ball.sampleGround();
        ball.z = ball.h;
        if (!area.contains(ball.x, ball.y)) {
            reports.finish(Outcome.OUT, ball.x, ball.y, ball.z);
        } else if (ball.h < 0 || ball.entersHazard()) {
            reports.finish(Outcome.WATER, ball.x, ball.y, ball.z);
        } else if (vz0 > 0 && vz0 > ball.hx * vx0 + ball.hy * vy0) {
            ball.flying = true;
            ball.vz = vz0;
            reports.event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
        }
    }

    public boolean isFinished() {
        return ball.outcome != null;
    }

    /** The result; only valid once {@link #isFinished()}. */
    public ShotResult result() {
        if (ball.outcome == null) throw new IllegalStateException("the stroke has not finished");
        return new ShotResult(ball.outcome, ball.endX, ball.endY, ball.t, ball.steps, ball.endZ, reports.events());
    }

    public double x() { return ball.x; }
    public double y() { return ball.y; }
    public double vx() { return ball.vx; }
    public double vy() { return ball.vy; }
    /** Height of the ball's contact point (its lowest point): the terrain height while it rolls. */
    public double z() { return ball.z; }
    /** Vertical velocity: in flight its own, while rolling the rate at which the ground under it rises. */
    public double vz() { return ball.verticalSpeed(); }
    public boolean isFlying() { return ball.flying; }
    public double time() { return ball.t; }
    public int steps() { return ball.steps; }
    /** The terrain height under the ball. */
    public double height() { return ball.h; }

    /** Advances the ball by one step (or ends the stroke). Does nothing once finished. */
    public void step() {
        BallState b = ball;
        if (b.outcome != null) return;
        double remaining = dt;
        int pieces = 0;
        while (pieces < MAX_PIECES) {
            b.resume = false;
            b.subPiece = false;
            remaining -= b.flying ? flight.piece(remaining) : rolling.piece(remaining);
            if (!b.resume || b.outcome != null || remaining <= 1e-9 * dt) return;
            // A sub-step the error control asked for is no contact: it does not count towards a wedge.
            if (!b.subPiece) pieces++;
        }
        // Wedged: more contacts in one step than we follow. The ball stops where it is for the rest of it.
        b.t += remaining;
        b.vx = 0;
        b.vy = 0;
        b.vz = 0;
    }

    /**
     * Ends the stroke as out of play where the ball is: for the game, when a step has thrown
     * {@link NonFiniteMotionException} (the ball reached terrain that is not finite), so the
     * player gets the ball back with a penalty instead of a crash.
     */
    public void endOutOfPlay() {
        if (ball.outcome == null) reports.finish(Outcome.OUT, ball.x, ball.y, ball.z);
    }

    /** Runs the stroke to its end. */
    public ShotResult run() {
        while (ball.outcome == null) step();
        return result();
    }
}
