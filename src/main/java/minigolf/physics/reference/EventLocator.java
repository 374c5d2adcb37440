package minigolf.physics.reference;

import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.physics.PlayArea;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * Finds the first event inside an accepted step on the integrator's dense output. Each event is a
 * predicate of the state that turns true; the step is sampled at a few points and the first
 * switch is bisected to {@link #TIME_TOLERANCE}. Events are located on the smooth interpolant, so
 * their accuracy is the integrator's, not the step's.
 */
final class EventLocator {
    enum Type {
        /** Leaves the bounds or enters a deleted cell. */
        OUT,
        /** h < 0. */
        WATER,
        /** Crosses into another friction zone: the integration restarts there. */
        ZONE,
        /** |v| falls below {@link ReferenceSimulator#TINY_SPEED}: the ball is about to stop. */
        SLOW,
        /** a·v turns from negative to ≥ 0: a local minimum of the speed. */
        MIN_SPEED,
        /** (p − c)·v turns from negative to ≥ 0: the path's closest approach to the hole. */
        CLOSEST,
        /** vᵀHv < −g: the ground curves away faster than gravity can hold the ball. */
        TAKE_OFF,
        /** A ball leaning on an obstacle is no longer pulled towards it, or is past its end. */
        LEAVE_OBSTACLE,
        /** The push under the ball is no longer the one held: a push zone's edge; the integration restarts there. */
        PUSH,
        /** The ball's centre enters a teleport's entry. */
        TELEPORT
    }

    static final double TIME_TOLERANCE = 1e-12;
    /** Samples per step; the step is short (≤ 20 ms), so nothing switches twice between two. */
    private static final int SAMPLES = 4;
    private static final Type[] TYPES = Type.values();

    private final DormandPrince stepper;
    private final RollingEquations equations;
    private final ReferenceFriction friction;
    private final ReferenceLean lean;
    private final PlayArea area;
    private final Terrain terrain;
    private final Hole hole;
    private final boolean capture;
    private final double g;
    private final double[] state = new double[4], accel = new double[2];
    private final boolean[] before = new boolean[TYPES.length], armed = new boolean[TYPES.length];

    /** The last event found: its type and a bracket [lo, hi] of its time (hi is past the switch). */
    Type type;
    double lo, hi;

    private final ReferenceForces forces;
    private final ReferenceTeleports teleports;
    private final double[] start = new double[4];

    EventLocator(World world, DormandPrince stepper, RollingEquations equations, ReferenceFriction friction,
                 ReferenceLean lean, ReferenceForces forces, ReferenceTeleports teleports) {
        this.forces = forces;
        this.teleports = teleports;
        this.lean = lean;
        this.stepper = stepper;
        this.equations = equations;
        this.friction = friction;
        this.area = world.playArea();
        this.terrain = world.terrain();
        this.hole = world.hole();
        this.capture = hole.rule() == HoleRule.CAPTURE;
        this.g = world.physics().gravity();
    }

    /**
     * The first event in (from, to] of the last accepted step, or false when there is none (the
     * simulator passes an obstacle contact's time as {@code to}: nothing after it happens).
     */
    boolean scan(double from, double to) {
        stepper.interpolate(from, state);
        for (Type t : TYPES) before[t.ordinal()] = holds(t, state);
        for (Type t : TYPES) armed[t.ordinal()] = !before[t.ordinal()];
        double sa = from;
        for (int s = 1; s <= SAMPLES; s++) {
            double sb = s == SAMPLES ? to : from + (to - from) * s / SAMPLES;
            if (!(sb > sa)) continue;
            stepper.interpolate(sa, start);
            stepper.interpolate(sb, state);
            type = null;
            for (Type t : TYPES) {
                if (t == Type.TELEPORT) {
                    if (teleports.none()) continue;
                    // An entry may be crossed between two samples: the chord between them says so,
                    // then a moment inside is looked for and the entry bisected from before it.
                    double inside = teleports.insideBetween(stepper, sa, sb, start, state);
                    if (Double.isNaN(inside)) continue;
                    double[] bracket = bisect(t, sa, inside);
                    if (type == null || bracket[1] < hi) {
                        type = t;
                        lo = bracket[0];
                        hi = bracket[1];
                    }
                    stepper.interpolate(sb, state);
                    continue;
                }
                if (!armed[t.ordinal()] || !holds(t, state)) continue;
                double[] bracket = bisect(t, sa, sb);
                if (type == null || bracket[1] < hi) {
                    type = t;
                    lo = bracket[0];
                    hi = bracket[1];
                }
            }
            if (type != null) return true;
            sa = sb;
        }
        return false;
    }

    /** The state at time t on the dense output, into out. */
    void stateAt(double t, double[] out) {
        stepper.interpolate(t, out);
    }

    private final double[] bracket = new double[2], probe = new double[4];

    private double[] bisect(Type t, double a, double b) {
        while (b - a > TIME_TOLERANCE) {
            double mid = 0.5 * (a + b);
            if (mid <= a || mid >= b) break;
            stepper.interpolate(mid, probe);
            if (holds(t, probe)) b = mid; else a = mid;
        }
        bracket[0] = a;
        bracket[1] = b;
        return bracket;
    }

    private boolean holds(Type t, double[] y) {
        double x = y[0], yy = y[1], vx = y[2], vy = y[3];
        switch (t) {
            case OUT:
                return !area.contains(x, yy);
            case WATER:
                return terrain.height(x, yy) < 0;
            case ZONE:
                return friction.hasZones() && friction.zoneAt(x, yy) != friction.heldZone();
            case SLOW:
                return vx * vx + vy * vy < ReferenceSimulator.TINY_SPEED * ReferenceSimulator.TINY_SPEED;
            case MIN_SPEED:
                equations.acceleration(y, accel, 0);
                return accel[0] * vx + accel[1] * vy >= 0;
            case CLOSEST:
                return capture && (x - hole.position().x()) * vx + (yy - hole.position().y()) * vy >= 0;
            case TAKE_OFF:
                // The curvature is a central difference across 10 µm: at the play area's edge it
                // would straddle the bounds (where a grid is extended flat) and launch a ball that
                // is simply leaving; that ball is out where it crosses, flying or not.
                return equations.curvatureTimesSpeedSquared(x, yy, vx, vy) < -g && insideAhead(x, yy, vx, vy);
            case LEAVE_OBSTACLE:
                return lean.leavesAt(x, yy);
            case PUSH:
                return forces.hasPushes() && forces.pushChangedAt(x, yy);
            case TELEPORT:
                return teleports.entryAt(x, yy) >= 0;
            default:
                throw new AssertionError(t);
        }
    }

    /** Whether the point 10 µm ahead along v (the curvature's reach) is still in play. */
    private boolean insideAhead(double x, double y, double vx, double vy) {
        double speed = Math.hypot(vx, vy);
        return speed == 0 || area.contains(x + 1e-5 * vx / speed, y + 1e-5 * vy / speed);
    }
}
