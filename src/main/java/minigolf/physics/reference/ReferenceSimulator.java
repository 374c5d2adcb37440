package minigolf.physics.reference;

import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * An independent reference for rolling strokes: the models of docs/course-format.md integrated by
 * an adaptive Dormand–Prince 5(4) method at tolerance {@value #TOLERANCE} (m and m/s per step),
 * every event located on its dense output to 1e-12 s, and the "Coming to rest" rule applied as
 * written. It shares no stepping, stopping, capture or hazard code with the engine
 * ({@code minigolf.physics.Stroke}); only the course's geometry and lookups (terrain, friction,
 * play area, the obstacles' swept-sphere test).
 *
 * <p>A ball leaves the ground (a chip, the take-off criterion vᵀHv &lt; −g, an obstacle bounce
 * upwards faster than a 1 mm hop) into {@link ReferenceFlight}. A ball that the slope presses
 * against an obstacle settles against it and rolls along it ({@link ReferenceLean}). A shot that
 * exceeds {@value #MAX_STEPS} accepted steps or {@value #MAX_CONTACTS} obstacle contacts (a ball
 * wedged in a corner between obstacles) is returned not covered. Several times the engine's work
 * per shot. Not thread-safe; one per thread. It knows the course's main hole only (a course's
 * {@code extraHoles} are plain ground to it).
 */
public final class ReferenceSimulator {
    public static final double TOLERANCE = 1e-10;
    /** v_rest of the rule: a local minimum of the speed at or below it stops the ball. */
    public static final double REST_SPEED = 1e-3;
    /**
     * Below this speed a ball still decelerating is finished analytically: v/|v| is singular at 0,
     * and from here the ball rolls at most TINY_SPEED²/(2a) further (5e-11 m at a = 0.01 m/s²).
     */
    static final double TINY_SPEED = 1e-6;
    static final long MAX_STEPS = 1_000_000;
    static final int MAX_CONTACTS = 1_000;
    private static final double MAX_STEP = 0.02;
    /** The crease test's probe: 1 mm down the slope. */
    private static final double CREASE_PROBE = 1e-3;

    private final World world;
    private final Terrain terrain;
    private final Hole hole;
    private final double maxTime;
    private final ReferenceFriction friction;
    private final RollingEquations equations;
    private final DormandPrince stepper;
    private final EventLocator events;
    private final ObstacleContact obstacles;
    private final ReferenceFlight flight;
    private final ReferenceLean lean;
    private final ReferenceForces forces;
    private final ReferenceTeleports teleports;
    private final double[] y = new double[4], a = new double[2], sample = new double[3], pulled = new double[2],
            force = new double[2];
    private double t;
    private long steps;
    private int contacts, launches;
    /** Contacts with moving obstacles in this stroke: past {@value #MOST_MOVING_CONTACTS} the ball is caught (out). */
    private int movingContacts;
    /** Where the shot was played from: a crushed or caught ball goes back there (out). */
    private double shotX, shotY;
    static final int MOST_MOVING_CONTACTS = 500;
    /** The course clock at the shot. */
    private double clock;
    /** The frame (of 1/60 s) in which the last contacts came, how many, and whether a moving obstacle was among them. */
    private long contactFrame = -1;
    private int frameContacts;
    private boolean frameMoving;

    public ReferenceSimulator(World world) {
        this(world, SimulationSettings.DEFAULT_MAX_TIME);
    }

    /** @param maxTime simulated seconds after which the stroke ends as {@code timeout}, as the engine's */
    public ReferenceSimulator(World world, double maxTime) {
        this(world, maxTime, TOLERANCE);
    }

    /** With another error tolerance per step (tests check that the reference has converged). */
    ReferenceSimulator(World world, double maxTime, double tolerance) {
        this.world = world;
        this.terrain = world.terrain();
        this.hole = world.hole();
        this.maxTime = maxTime;
        this.friction = new ReferenceFriction(world);
        this.lean = new ReferenceLean(world);
        this.forces = new ReferenceForces(world);
        this.teleports = new ReferenceTeleports(world);
        lean.with(forces, new ReferenceGates(world));
        this.equations = new RollingEquations(world, friction, lean, forces);
        this.stepper = new DormandPrince(new double[] {tolerance, tolerance, tolerance, tolerance});
        this.events = new EventLocator(world, stepper, equations, friction, lean, forces, teleports);
        this.obstacles = new ObstacleContact(world, stepper, false);
        this.flight = new ReferenceFlight(world, maxTime, tolerance);
    }

    public static String description() {
        return "adaptive Dormand-Prince 5(4), tol 1e-10 m and m/s per step, events to 1e-12 s";
    }

    /** A rolling shot from (x0, y0) with horizontal velocity (vx, vy). */
    public ReferenceResult simulate(double x0, double y0, double vx, double vy) {
        return simulate(x0, y0, vx, vy, 0);
    }

    /** A shot with a vertical component: it flies if vz is above the ground's rise along (vx, vy). */
    public ReferenceResult simulate(double x0, double y0, double vx, double vy, double vz) {
        return simulateAt(0, x0, y0, vx, vy, vz);
    }

    /** A shot played at course clock {@code clockAtShot} (s), for courses with moving obstacles. */
    public ReferenceResult simulateAt(double clockAtShot, double x0, double y0, double vx, double vy, double vz) {
        clock = clockAtShot;
        shotX = x0;
        shotY = y0;
        obstacles.clockOffset = clockAtShot;
        flight.clockOffset(clockAtShot);
        teleports.reset();
        contactFrame = -1;
        y[0] = x0;
        y[1] = y0;
        y[2] = vx;
        y[3] = vy;
        t = 0;
        steps = 0;
        contacts = 0;
        movingContacts = 0;
        launches = 0;
        lean.off();
        friction.holdZone(friction.zoneAt(x0, y0));
        forces.holdPushAt(x0, y0);
        terrain.sample(x0, y0, sample);
        double rise = sample[1] * vx + sample[2] * vy;
        ReferenceResult end = null;
        if (vz > 0 && vz > rise) {
            end = fly(x0, y0, sample[0], vx, vy, vz);
        } else if (vx == 0 && vy == 0) {
            end = comeToRest();
        } else if (equations.curvatureTimesSpeedSquared(x0, y0, vx, vy) < -equations.gravity()) {
            end = fly(x0, y0, sample[0], vx, vy, rise);
        }
        return (end != null ? end : roll()).withCounts(launches, contacts);
    }

    /** Integrates until the stroke ends. */
    private ReferenceResult roll() {
        double h = 1e-3;
        stepper.restart();
        while (true) {
            if (t >= maxTime) return end(Outcome.TIMEOUT, y[0], y[1]);
            if (steps >= MAX_STEPS) return ReferenceResult.notCovered("more than " + MAX_STEPS + " steps", y[0], y[1], t, steps);
            double step = Math.min(Math.min(h, MAX_STEP), maxTime - t);
            double err = stepper.attempt(equations, t, y, step);
            if (err > 1) {
                h = DormandPrince.nextStep(step, err);
                if (h < 1e-15) return ReferenceResult.notCovered("step size underflow", y[0], y[1], t, steps);
                continue;
            }
            steps++;
            h = DormandPrince.nextStep(step, err);
            ReferenceResult done = handleStep(stepper.stepStart(), stepper.stepEnd());
            if (done != null) return done;
        }
    }

    /**
     * Looks for contacts and events in the accepted step [from, to] and acts on the first; returns
     * the result when the stroke ends there, else leaves (t, y) at where to go on from.
     */
    private ReferenceResult handleStep(double from, double to) {
        boolean contact = obstacles.find(from, to);
        double until = contact ? obstacles.time : to;
        double scanFrom = from;
        while (events.scan(scanFrom, until)) {
            switch (events.type) {
                case OUT:
                case WATER: {
                    // The first point past the edge, within 1e-12 s of the crossing.
                    events.stateAt(events.hi, y);
                    t = events.hi;
                    return end(events.type == EventLocator.Type.OUT ? Outcome.OUT : Outcome.WATER, y[0], y[1]);
                }
                case ZONE:
                    restartAt(events.hi);
                    friction.holdZone(friction.zoneAt(y[0], y[1]));
                    return null;
                case PUSH:
                    restartAt(events.hi);
                    forces.holdPushAt(y[0], y[1]);
                    return null;
                case TELEPORT: {
                    restartAt(events.hi);
                    lean.off();
                    teleports.send(teleports.entryAt(y[0], y[1]), y);
                    friction.holdZone(friction.zoneAt(y[0], y[1]));
                    forces.holdPushAt(y[0], y[1]);
                    return null;
                }
                case SLOW:
                    restartAt(events.hi);
                    finishStop();
                    return comeToRest();
                case MIN_SPEED:
                    events.stateAt(events.hi, y);
                    if (Math.hypot(y[2], y[3]) <= REST_SPEED) {
                        restartAt(events.hi);
                        y[2] = 0;
                        y[3] = 0;
                        return comeToRest();
                    }
                    scanFrom = events.hi;
                    break;
                case CLOSEST:
                    events.stateAt(events.hi, y);
                    if (captured(y[0], y[1], Math.hypot(y[2], y[3]))) {
                        t = events.hi;
                        return end(Outcome.HOLED, y[0], y[1]);
                    }
                    scanFrom = events.hi;
                    break;
                case LEAVE_OBSTACLE:
                    restartAt(events.hi);
                    lean.off();
                    return null;
                case TAKE_OFF: {
                    restartAt(events.hi);
                    terrain.sample(y[0], y[1], sample);
                    return fly(y[0], y[1], sample[0], y[2], y[3], sample[1] * y[2] + sample[2] * y[3]);
                }
                default:
                    throw new AssertionError(events.type);
            }
        }
        if (contact) {
            restartAt(obstacles.time);
            if (++contacts > MAX_CONTACTS) {
                return ReferenceResult.notCovered("more than " + MAX_CONTACTS + " obstacle contacts", y[0], y[1], t, steps);
            }
            if (crushed(obstacles.moving) || caught(obstacles.moving)) return end(Outcome.OUT, shotX, shotY);
            if (obstacles.respond(y)) {
                if (obstacles.moving) {
                    lean.off();
                    separate();
                } else {
                    lean.afterContact(y, obstacles.nx, obstacles.ny, obstacles.nz);
                }
            } else {
                lean.off();
                return fly(y[0], y[1], terrain.height(y[0], y[1]), obstacles.flight[0], obstacles.flight[1], obstacles.flight[2]);
            }
            return null;
        }
        stepper.accept(y);
        t = to;
        return null;
    }

    /**
     * A ball wedged by a moving obstacle is crushed (out of play): 16 contacts within one 1/60 s
     * frame of the stroke's time, a moving obstacle among them (docs/physics.md).
     */
    private boolean crushed(boolean moving) {
        long frame = (long) Math.floor(t * 60);
        if (frame != contactFrame) {
            contactFrame = frame;
            frameContacts = 0;
            frameMoving = false;
        }
        frameContacts++;
        frameMoving |= moving;
        return frameContacts > 16 && frameMoving;
    }

    /** Counts a moving obstacle's contact: whether the ball is now caught (docs/course-format.md). */
    private boolean caught(boolean moving) {
        return moving && ++movingContacts > MOST_MOVING_CONTACTS;
    }

    /** The least separation after a moving obstacle's contact (docs/physics.md), for the ball at y. */
    private void separate() {
        equations.pullAtRest(y[0], y[1], pulled);
        obstacles.separate(y, friction.kinetic(y[0], y[1]), Math.hypot(pulled[0], pulled[1]));
    }

    /**
     * A flight from the contact point (x, y, z); returns the stroke's end, or null with (t, y) where
     * it settled into rolling.
     */
    private ReferenceResult fly(double x, double yy, double z, double vx, double vy, double vz) {
        launches++;
        lean.off();
        flight.steps = steps;
        flight.contacts = contacts;
        flight.movingContacts = movingContacts;
        flight.shotX = shotX;
        flight.shotY = shotY;
        ReferenceResult end = flight.fly(x, yy, z, vx, vy, vz, t);
        steps = flight.steps;
        contacts = flight.contacts;
        movingContacts = flight.movingContacts;
        if (end != null) return end;
        System.arraycopy(flight.rolling, 0, y, 0, 4);
        t = flight.time;
        friction.holdZone(friction.zoneAt(y[0], y[1]));
        stepper.restart();
        if (Math.hypot(y[2], y[3]) < TINY_SPEED) {
            y[2] = 0;
            y[3] = 0;
            return comeToRest();
        }
        return null;
    }

    /** Cuts the integration at time tc of the last step: the state there becomes the new start. */
    private void restartAt(double tc) {
        events.stateAt(tc, y);
        t = tc;
        stepper.restart();
    }

    /**
     * The last {@link #TINY_SPEED} of a decelerating ball, at the deceleration along v it has
     * there: it moves |v|²/(2a∥) on along v and stops |v|/a∥ later.
     */
    private void finishStop() {
        double speed = Math.hypot(y[2], y[3]);
        equations.acceleration(y, a, 0);
        double along = -(a[0] * y[2] + a[1] * y[3]) / speed;
        if (along > 0 && speed > 0) {
            y[0] += y[2] / speed * speed * speed / (2 * along);
            y[1] += y[3] / speed * speed * speed / (2 * along);
            t += speed / along;
        }
        y[2] = 0;
        y[3] = 0;
    }

    /**
     * Rule 2 of "Coming to rest" at the ball's position: it stays (result) or starts rolling down
     * the slope (null, with (t, y) just after the start).
     */
    private ReferenceResult comeToRest() {
        double x = y[0], yy = y[1];
        lean.off();
        terrain.sample(x, yy, sample);
        double h = sample[0];
        // Gravity's pull with the forces' (course-format.md, "Forces"); the ground's slope without them.
        equations.pullAtRest(x, yy, pulled);
        double hx = pulled[0], hy = pulled[1], slope = Math.hypot(hx, hy);
        // Capture rule: a ball at rest within the radius passes there at speed 0, below v_c(1 − (δ/r)²).
        if (hole.rule() == HoleRule.CAPTURE && captured(x, yy, 0)) return end(Outcome.HOLED, x, yy);
        double mu = friction.holding(x, yy);
        boolean holds = slope <= mu || creaseHolds(x, yy, h, hx, hy, slope, mu) || lean.leansAtRest(x, yy, hx, hy);
        if (holds) {
            boolean inHole = hole.rule() == HoleRule.REST
                    && Math.hypot(x - hole.position().x(), yy - hole.position().y()) <= hole.radius();
            if (!inHole && !obstacles.movers().none()) return waitForMoving(x, yy, h);
            return end(inHole ? Outcome.HOLED : Outcome.STOPPED, x, yy);
        }
        // Rolling from rest: the limit of the equations as v → 0 down the slope; the first
        // 2·TINY_SPEED of speed is gained at that constant acceleration.
        friction.holdZone(friction.zoneAt(x, yy));
        forces.holdPushAt(x, yy);
        equations.fromRest(x, yy, a);
        double accel = Math.hypot(a[0], a[1]);
        double tau = 2 * TINY_SPEED / accel;
        y[0] = x + 0.5 * a[0] * tau * tau;
        y[1] = yy + 0.5 * a[1] * tau * tau;
        y[2] = a[0] * tau;
        y[3] = a[1] * tau;
        t += tau;
        stepper.restart();
        return null;
    }

    /**
     * Rule 2's crease clause: the ground 1 mm down the pull (hx, hy) is no more than μ·1 mm lower, the
     * forces' work over that millimetre (their mean at both ends) counted as a drop.
     */
    private boolean creaseHolds(double x, double yy, double h, double hx, double hy, double slope, double mu) {
        double ex = x - CREASE_PROBE * hx / slope, ey = yy - CREASE_PROBE * hy / slope;
        double ground = terrain.height(ex, ey);
        if (!forces.none()) {
            forces.at(x, yy, force);
            double wx = force[0], wy = force[1];
            forces.at(ex, ey, force);
            ground -= 0.5 * ((wx + force[0]) * (ex - x) + (wy + force[1]) * (ey - yy)) / equations.gravity();
        }
        return ground >= h - mu * CREASE_PROBE;
    }

    /**
     * A ball held at rest where moving obstacles are: the stroke ends unless one of them reaches it
     * within its longest period (the motions repeat); then the ball waits there until that moment,
     * is hit, and rolls on (null, with (t, y) after the contact), or the stroke ends out if it flies off.
     */
    private ReferenceResult waitForMoving(double x, double yy, double h) {
        double reach = obstacles.firstTouchStill(x, yy, h, t, obstacles.movers().longestPeriod());
        if (Double.isNaN(reach)) return end(Outcome.STOPPED, x, yy);
        if (reach >= maxTime) {
            t = maxTime;
            return end(Outcome.TIMEOUT, x, yy);
        }
        t = reach;
        y[2] = 0;
        y[3] = 0;
        if (++contacts > MAX_CONTACTS) {
            return ReferenceResult.notCovered("more than " + MAX_CONTACTS + " obstacle contacts", y[0], y[1], t, steps);
        }
        if (crushed(true) || caught(true)) return end(Outcome.OUT, shotX, shotY);
        friction.holdZone(friction.zoneAt(x, yy));
        forces.holdPushAt(x, yy);
        stepper.restart();
        if (!obstacles.respond(y)) {
            return fly(x, yy, h, obstacles.flight[0], obstacles.flight[1], obstacles.flight[2]);
        }
        separate();
        return null;
    }

    /** The capture rule: within the radius at a speed below v_c·(1 − (δ/r)²). */
    private boolean captured(double x, double yy, double speed) {
        double ratio = Math.hypot(x - hole.position().x(), yy - hole.position().y()) / hole.radius();
        return ratio <= 1 && speed < hole.effectiveCaptureSpeed() * (1 - ratio * ratio);
    }

    private ReferenceResult end(Outcome outcome, double x, double yy) {
        return new ReferenceResult(outcome, x, yy, t, true, "", steps);
    }

    public World world() {
        return world;
    }
}
