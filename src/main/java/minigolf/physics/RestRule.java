package minigolf.physics;

import minigolf.collision.Hit;
import minigolf.terrain.Terrain;

/**
 * The rule by which a rolling ball comes to rest and stays there (docs/course-format.md, "Coming
 * to rest"): when it stops, and whether the ground (or an obstacle it leans on) holds it.
 * It remembers one decision per approach to a turn, so a {@link Stroke} has one of its own.
 */
public final class RestRule {
    /** The rest rule's speed (m/s): a ball whose speed passes through a minimum this low stops there. */
    public static final double REST_SPEED = 0.001;
    /** How far down the slope the rule probes the ground at a crease (m). */
    public static final double CREASE_PROBE = 0.001;
    /** How long before it would turn (s) a ball on ground steeper than mu_k has the rule decided. */
    static final double TURN_HORIZON = 1.0 / 15;

    private final Terrain terrain;
    private final FrictionField friction;
    /** What the ball can lean on at rest: still obstacles and gates; null without them. */
    private final Solids solids;
    private final double ballRadius;
    private final double gravity;
    /** Push zones and magnets; null without them. */
    private final ForceField forces;
    private final Hit hit = new Hit();
    private final double[] scratch = new double[3];
    private Turn turn = Turn.UNDECIDED;

    RestRule(World world) {
        this(world, Solids.of(world));
    }

    /** With the stroke's solids (null without any), so the rule shares their buffers. */
    RestRule(World world, Solids solids) {
        this.terrain = world.terrain();
        this.friction = world.friction();
        this.solids = solids;
        this.ballRadius = world.physics().ballRadius();
        this.gravity = world.physics().gravity();
        this.forces = world.forces();
    }

    /** Whether the ball is turning on ground steeper than mu_k and the rule sends it back down. */
    boolean rollsBack() {
        return turn == Turn.ROLLS_BACK;
    }

    /** The ball is speeding up, or not braking: a later approach to a turn is decided afresh. */
    void forget() {
        turn = Turn.UNDECIDED;
    }

    /**
     * The rest rule (docs/course-format.md) for a braking ball: the time within the coming tau
     * at which it stops, or -1. On ground no steeper than mu_k its speed reaches 0 (at constant
     * deceleration, after speed / deceleration). On steeper ground it turns round, and stops only
     * if its lowest speed on the way is at most {@link #REST_SPEED}. That is decided once, from the
     * tangent plane's closed form, when the ball comes within {@link #TURN_HORIZON} of turning
     * (whatever the step, so the decision does not depend on it): nearer the turn the
     * integrator's sideways speed loses its accuracy (it falls like (t0 - t)^0.4).
     */
    double stopWithin(double tau, double speed, double deceleration, double slope,
                      double vx, double vy, double hx, double hy, double muK) {
        if (slope <= muK) {
            turn = Turn.UNDECIDED;
            return speed <= deceleration * tau ? speed / deceleration : -1;
        }
        if (speed > gravity * (slope + muK) * Math.max(TURN_HORIZON, 2 * tau) + REST_SPEED) {
            turn = Turn.UNDECIDED;
            return -1;
        }
        if (turn == Turn.UNDECIDED) {
            boolean stops = TurningPoint.minimumSpeed(vx, vy, hx, hy, muK) <= REST_SPEED;
            turn = stops ? Turn.STOPS : Turn.ROLLS_BACK;
        }
        // Deciding to stop, it stops at the turn, where its speed is at most REST_SPEED.
        if (turn != Turn.STOPS || speed > deceleration * tau + REST_SPEED) return -1;
        return Math.min(speed / deceleration, tau);
    }

    /** The rest rule's decision for a ball approaching its turn on ground steeper than mu_k. */
    enum Turn { UNDECIDED, STOPS, ROLLS_BACK }

    /**
     * Whether the ground holds a ball at rest: static (or kinetic) friction is at least the slope
     * (the pull gradient (hx, hy): the ground's, tilted by push zones and magnets), or, at a crease
     * where the slope jumps (a V-shaped valley's floor, a cone's tip, where two pushes meet), the
     * ground one probe further down the pull is no lower than friction allows, the force's work over
     * the probe (its mean at both ends) counted as a drop of the ground.
     */
    boolean holds(double x, double y, double h, double hx, double hy, double muK) {
        double slope = Math.sqrt(hx * hx + hy * hy);
        double mu = Math.max(friction.staticFriction(x, y), muK);
        if (mu >= slope) return true;
        double d = CREASE_PROBE / slope;
        double ex = x - hx * d, ey = y - hy * d;
        double ground = terrain.height(ex, ey);
        if (forces != null) ground -= forceWork(x, y, ex, ey) / gravity;
        if (ground >= h - mu * CREASE_PROBE) return true;
        return leansOnObstacle(x, y, h, ex, ey);
    }

    /** The work per unit mass of the push zones and magnets from (x, y) to (ex, ey): their mean force at both ends along the way. */
    private double forceWork(double x, double y, double ex, double ey) {
        forces.force(x, y, scratch);
        double fx = scratch[0], fy = scratch[1];
        forces.force(ex, ey, scratch);
        return 0.5 * ((fx + scratch[0]) * (ex - x) + (fy + scratch[1]) * (ey - y));
    }

    /**
     * Whether a ball at rest, pulled down the slope towards (ex, ey), leans on an obstacle there
     * (within the crease probe): the obstacle takes the push, and it rests against it. Without
     * this a ball rolling from rest into a wall is cut at the wall every step and never finishes.
     */
    private boolean leansOnObstacle(double x, double y, double h, double ex, double ey) {
        if (solids == null || !solids.anyStillNear(Math.min(x, ex), Math.min(y, ey), Math.max(x, ex), Math.max(y, ey))) {
            return false;
        }
        double r = ballRadius;
        return solids.sweepStill(x, y, h + r, ex, ey, terrain.height(ex, ey) + r, hit);
    }

}
