package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * Where inside a rolling step something changes, found by bisection (on the step's cubic, then
 * confirmed on trial sub-steps, or on trial sub-steps alone): the first moment the ball is in a
 * hazard (water, outside the bounds), the end of the obstacle it leans on, and a friction or push
 * zone's edge. A step is cut there, so each is met at its place, not at a step's end.
 */
final class StepLocator {
    /** Bisection halvings when locating an event inside a step: dt / 2^50 is far below 1 mm. */
    static final int LOCATE_ITERATIONS = 50;
    /**
     * How far apart (m) the last safe point and the first point in a hazard may lie once located:
     * a step of dt / 2^50 moves a ball at 5 m/s by 10^-16 m, so anything near this is a path
     * that jumps.
     */
    static final double LOCATE_GAP = 1e-6;
    /**
     * A crossing found on the step's cubic is confirmed by trial steps this fraction of the step
     * either side of it (a ball at 5 m/s in a step of 8 dt: 7e-8 m apart).
     */
    static final double CONFIRM = 1e-7;

    /**
     * As {@link #CONFIRM}, for a zone's edge: a ball pushed towards an edge from both sides (a
     * funnel of two push zones) crosses it step after step, and at 1e-7 of a step past it each
     * time a shot on `windmill-push` ended 0.38 mm from the reference instead of 0.04 mm.
     */
    static final double EDGE_CONFIRM = 1e-9;

    private final BallState ball;
    private final RollingTrial trial;
    private final RollingStep rolling;
    private final Terrain terrain;
    private final GroundCache ground;
    private final FrictionField friction;
    /** Push zones and magnets; null without them. */
    private final ForceField forces;
    private final PlayArea area;
    private final double[] push = new double[2];

    StepLocator(BallState ball, RollingTrial trial, RollingStep rolling, Terrain terrain, GroundCache ground,
                FrictionField friction, ForceField forces, PlayArea area) {
        this.ground = ground;
        this.forces = forces;
        this.ball = ball;
        this.trial = trial;
        this.rolling = rolling;
        this.terrain = terrain;
        this.friction = friction;
        this.area = area;
    }

    /** Whether (qx, qy) is in play: inside the bounds, not over a deleted cell. */
    boolean inPlay(double qx, double qy) {
        return area.contains(qx, qy);
    }

    /** How far (m) (qx, qy) lies inside the bounds, negative outside ({@link PlayArea#depthInside}). */
    double depthInside(double qx, double qy) {
        return area.depthInside(qx, qy);
    }

    /**
     * The hazard at a step's end (qx, qy), as {@link #hazardAt}, sampling the ground there fully:
     * the next step starts with that sample.
     */
    Outcome hazardAtEnd(double qx, double qy) {
        if (!area.contains(qx, qy)) return Outcome.OUT;
        if (ground.at(qx, qy)[0] < 0) return Outcome.WATER;
        if (friction.entersHazard(qx, qy)) return Outcome.WATER;
        return null;
    }

    /** The hazard at (qx, qy): OUT outside the bounds, WATER below the water's surface, else null. */
    Outcome hazardAt(double qx, double qy) {
        if (!area.contains(qx, qy)) return Outcome.OUT;
        if (terrain.height(qx, qy) < 0) return Outcome.WATER;
        if (friction.entersHazard(qx, qy)) return Outcome.WATER;
        return null;
    }

    /**
     * The first sub-step length at which the ball is in a hazard; on entry the trial holds the
     * whole step (whose end is in the hazard), on return the step of the length found. The
     * crossing is found first on the cubic through the step's ends with their velocities (a
     * terrain height per try, against a trial step's several samples), then confirmed on the
     * trial steps a hair either side of it ({@link #CONFIRM}); where that fails, by bisection on
     * trial steps. The end found must lie within {@link #LOCATE_GAP} of the last point found
     * safe: otherwise the ball's path jumps there, on ground that changes faster than any step can
     * follow (a height like 0.2 + 0.01 sin(1e15 x)), and the stroke cannot go on.
     *
     * @throws NonFiniteMotionException if the path jumps where the hazard begins
     */
    double hazard(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        double hazard = hazardOnCubic(tau);
        double inside = Math.min(tau, (hazard + CONFIRM) * tau), before = Math.max(0, (hazard - CONFIRM) * tau);
        trial.run(before, kind, a1x, a1y);
        double safeX = trial.nx, safeY = trial.ny;
        if (hazardAt(safeX, safeY) == null) {
            trial.run(inside, kind, a1x, a1y);
            if (hazardAt(trial.nx, trial.ny) != null) return confirmed(inside, safeX, safeY);
        }
        return bisect(tau, kind, a1x, a1y);
    }

    /** A test of a point in the plane: whether something has happened there. */
    private interface PointTest {
        boolean at(double x, double y);
    }

    /** The friction zone the step being cut at a zone's edge started in. */
    private int startZone;
    private final PointTest pastEdge = (x, y) -> !sameRegion(startZone, x, y);

    /**
     * Where on the cubic through the step's ends with their velocities (the trial holds the whole
     * step; its end passes the test) the test first holds, by bisection: the fraction of the step
     * at the first point found that passes. The bisection stops once the point is within an eighth
     * of {@code confirm} of the crossing (33 halvings for {@link #EDGE_CONFIRM} instead of 50): the trial
     * steps that confirm it lie {@code confirm} either side, so the rest would move the end found
     * by less than an eighth of that (at most 1e-8 m for a hazard).
     */
    private double onCubic(double tau, PointTest test, double confirm) {
        BallState b = ball;
        double x0 = b.x, y0 = b.y, mx0 = b.vx * tau, my0 = b.vy * tau;
        double x1 = trial.nx, y1 = trial.ny, mx1 = trial.nvx * tau, my1 = trial.nvy * tau;
        double before = 0, after = 1;
        for (int k = 0; k < LOCATE_ITERATIONS && after - before > 0.125 * confirm; k++) {
            double mid = 0.5 * (before + after);
            if (test.at(PathSweep.hermite(mid, x0, mx0, x1, mx1), PathSweep.hermite(mid, y0, my0, y1, my1))) after = mid; else before = mid;
        }
        return after;
    }

    /**
     * As {@link #onCubic} for water and the bounds (the test: {@link #hazardAt}), to the same
     * {@link #CONFIRM} / 8, but by false position (the Illinois variant) on the point's clearance,
     * its height above the water and its depth inside the bounds, which cross zero smoothly where
     * the ball enters a hazard: 3 to 5 points on the cubic instead of 27 halvings, each a terrain
     * height (a lake shot that ends in the water asks 35 heights instead of 57). The test still decides each point; where the clearance disagrees with it (a hazard
     * zone, a deleted cell) the rest is bisection.
     */
    private double hazardOnCubic(double tau) {
        BallState b = ball;
        double x0 = b.x, y0 = b.y, mx0 = b.vx * tau, my0 = b.vy * tau;
        double x1 = trial.nx, y1 = trial.ny, mx1 = trial.nvx * tau, my1 = trial.nvy * tau;
        double before = 0, after = 1;
        // The clearance at both ends of the bracket (the end's height is the step end's sample).
        double safe = Math.min(b.h, area.depthInside(x0, y0));
        double wet = area.contains(x1, y1) ? Math.min(ground.at(x1, y1)[0], area.depthInside(x1, y1)) : area.depthInside(x1, y1);
        boolean interpolate = safe >= 0 && wet <= 0;
        int side = 0; // the side the last point fell on: -1 safe, 1 hazard
        double close = 0.125 * CONFIRM;
        for (int k = 0; k < LOCATE_ITERATIONS && after - before > close; k++) {
            double u = interpolate && safe > wet ? before + (after - before) * safe / (safe - wet) : 0.5 * (before + after);
            // Never at (or within a sixteenth of the tolerance of) an end: each point shrinks the bracket.
            double keep = 0.5 * close;
            u = Math.max(before + keep, Math.min(after - keep, u));
            double px = PathSweep.hermite(u, x0, mx0, x1, mx1), py = PathSweep.hermite(u, y0, my0, y1, my1);
            boolean hazard;
            double clearance;
            if (!area.contains(px, py)) {
                hazard = true;
                clearance = area.depthInside(px, py);
            } else {
                double h = terrain.height(px, py);
                hazard = h < 0 || friction.entersHazard(px, py);
                clearance = Math.min(h, area.depthInside(px, py));
            }
            if (hazard) {
                after = u;
                wet = clearance;
                if (side == 1) safe *= 0.5; // Illinois: an end kept twice counts half
                side = 1;
            } else {
                before = u;
                safe = clearance;
                if (side == -1) wet *= 0.5;
                side = -1;
            }
            interpolate &= hazard ? clearance <= 0 : clearance >= 0;
        }
        return after;
    }

    /** The hazard's sub-step found by bisection on trial steps from the step's start. */
    private double bisect(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        double safe = 0, hazard = tau;
        double safeX = ball.x, safeY = ball.y;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (safe + hazard);
            trial.run(mid, kind, a1x, a1y);
            if (hazardAt(trial.nx, trial.ny) != null) {
                hazard = mid;
            } else {
                safe = mid;
                safeX = trial.nx;
                safeY = trial.ny;
            }
        }
        trial.run(hazard, kind, a1x, a1y);
        return confirmed(hazard, safeX, safeY);
    }

    /** The trial holds the hazard's sub-step of this length: its end must be within LOCATE_GAP of the safe point. */
    private double confirmed(double length, double safeX, double safeY) {
        if (!(Math.hypot(trial.nx - safeX, trial.ny - safeY) <= LOCATE_GAP)) {
            throw NonFiniteMotionException.unresolved(safeX, safeY);
        }
        return length;
    }

    /** The first sub-step length at which the obstacle the ball leans on is out of its reach, by bisection. */
    double obstacleEnd(Leaning lean, double tau, RollingStep.Kind kind, double a1x, double a1y) {
        double on = 0, off = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (on + off);
            trial.run(mid, kind, a1x, a1y);
            if (lean.touches(trial.nx, trial.ny)) on = mid; else off = mid;
        }
        return off;
    }

    /**
     * Friction jumps at a zone's edge, and so does the push at a push zone's edge: an integrator
     * step across the jump loses its order. If the step would end in another zone (or under another
     * push), it is shortened to end just past the edge, with the friction and the push of where it
     * started (frozen in {@link RollingStep#frozenMuK} and {@link RollingStep#pushFrozen} until the
     * step is committed); the next step starts with the new ones. The edge is found on the step's
     * cubic and confirmed as a hazard is (fifty trial steps of bisection cost 13% of a shot on
     * `windmill-push`); where that fails (one crossing in five there), within a wider bracket
     * round it, and only then on the whole step.
     */
    double zoneEdge(double tau, double a1x, double a1y) {
        int zone = friction.zoneAt(ball.x, ball.y);
        if (!trial.holds(tau)) trial.run(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
        if (sameRegion(zone, trial.nx, trial.ny)) return tau;
        startZone = zone;
        rolling.frozenMuK = ball.muK;
        if (forces != null) {
            forces.push(ball.x, ball.y, push);
            rolling.pushFrozen = true;
            rolling.frozenPushX = push[0];
            rolling.frozenPushY = push[1];
        }
        // The whole step again with the start's friction and push: a smooth path, whose cubic
        // the edge is found on.
        trial.run(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
        double edge = onCubic(tau, pastEdge, EDGE_CONFIRM);
        // Found on the step's cubic, confirmed by trial steps a hair either side; where the cubic
        // strays from the trial steps by more than that hair (its own interpolation error), by
        // trial steps EDGE_BRACKET either side, and bisection between them; where even that fails,
        // by bisection on trial steps from the whole step. Each ends within EDGE_CONFIRM of the
        // step past the edge.
        for (int pass = 0; pass < 2; pass++) {
            double hair = pass == 0 ? EDGE_CONFIRM : EDGE_BRACKET;
            double before = Math.max(0, (edge - hair) * tau), past = Math.min(tau, (edge + hair) * tau);
            trial.run(before, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (!sameRegion(zone, trial.nx, trial.ny)) continue;
            trial.run(past, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (!sameRegion(zone, trial.nx, trial.ny)) return pass == 0 ? past : edgeBetween(zone, before, past, tau, a1x, a1y);
        }
        return edgeBetween(zone, 0, tau, tau, a1x, a1y);
    }

    /**
     * As {@link #EDGE_CONFIRM}, for the bracket tried where the hair's fails: the cubic's
     * interpolation error (micrometres at most) against a step's travel (a ball at 0.01 m/s in a
     * step of dt moves 1.7e-4 m, so 1e-5 of it is 1.7e-9 m: less than the error only where the
     * cubic is off by more, and then the whole step is bisected).
     */
    static final double EDGE_BRACKET = 1e-5;

    /**
     * The step's length just past the zone's edge between trial steps {@code inside} (in the
     * region) and {@code beyond} (not), by bisection on trial steps down to EDGE_CONFIRM of the
     * whole step tau: the first trial step found past the edge.
     */
    private double edgeBetween(int zone, double inside, double beyond, double tau, double a1x, double a1y) {
        for (int k = 0; k < LOCATE_ITERATIONS && beyond - inside > EDGE_CONFIRM * tau; k++) {
            double mid = 0.5 * (inside + beyond);
            trial.run(mid, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (sameRegion(zone, trial.nx, trial.ny)) inside = mid; else beyond = mid;
        }
        return beyond;
    }

    /** Whether (x, y) lies in another friction zone or under another push than the ball. */
    boolean leavesRegion(double x, double y) {
        return !sameRegion(friction.zoneAt(ball.x, ball.y), x, y);
    }

    /** Whether (x, y) has the friction zone {@code zone} and the push of the ball's position. */
    private boolean sameRegion(int zone, double x, double y) {
        if (friction.zoneAt(x, y) != zone) return false;
        if (forces == null || !forces.hasPushZones()) return true;
        // The push at the ball's position, kept while the ball stays there (a location asks many times).
        if (ball.x != pushAtX || ball.y != pushAtY) {
            forces.push(ball.x, ball.y, pushHere);
            ballPushX = pushHere[0];
            ballPushY = pushHere[1];
            pushAtX = ball.x;
            pushAtY = ball.y;
        }
        forces.push(x, y, pushHere);
        return pushHere[0] == ballPushX && pushHere[1] == ballPushY;
    }

    /** The push at (pushAtX, pushAtY), the ball's position when last asked; a buffer. */
    private double pushAtX = Double.NaN, pushAtY = Double.NaN, ballPushX, ballPushY;
    private final double[] pushHere = new double[2];
}
