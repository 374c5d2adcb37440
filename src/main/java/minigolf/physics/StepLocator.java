package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * Where inside a rolling step something changes, found by bisection on trial sub-steps: the first
 * moment the ball is in a hazard (water, outside the bounds), the end of the obstacle it leans on,
 * and a friction zone's edge. A step is cut there, so each is met at its place, not at a step's end.
 */
final class StepLocator {
    /** Bisection halvings when locating an event inside a step: dt / 2^50 is far below 1 mm. */
    static final int LOCATE_ITERATIONS = 50;

    private final BallState ball;
    private final RollingTrial trial;
    private final RollingStep rolling;
    private final Terrain terrain;
    private final FrictionField friction;
    private final PlayArea area;

    StepLocator(BallState ball, RollingTrial trial, RollingStep rolling, Terrain terrain, FrictionField friction,
                PlayArea area) {
        this.ball = ball;
        this.trial = trial;
        this.rolling = rolling;
        this.terrain = terrain;
        this.friction = friction;
        this.area = area;
    }

    /** The hazard at (qx, qy): OUT outside the bounds, WATER below the water's surface, else null. */
    Outcome hazardAt(double qx, double qy) {
        if (!area.contains(qx, qy)) return Outcome.OUT;
        if (terrain.height(qx, qy) < 0) return Outcome.WATER;
        if (friction.entersHazard(qx, qy)) return Outcome.WATER;
        return null;
    }

    /** The first sub-step length at which the ball is in a hazard, found by bisection. */
    double hazard(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        double safe = 0, hazard = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (safe + hazard);
            trial.run(mid, kind, a1x, a1y);
            if (hazardAt(trial.nx, trial.ny) != null) hazard = mid; else safe = mid;
        }
        return hazard;
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
     * Friction jumps at a zone's edge, and an integrator step across the jump loses its order.
     * If the step would end in another zone, it is shortened to end just past the edge, with the
     * friction of the zone it started in (frozen in {@link RollingStep#frozenMuK} until the step
     * is committed); the next step starts with the new zone's friction.
     */
    double zoneEdge(double tau, double a1x, double a1y) {
        int zone = friction.zoneAt(ball.x, ball.y);
        if (!trial.holds(tau)) trial.run(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
        if (friction.zoneAt(trial.nx, trial.ny) == zone) return tau;
        rolling.frozenMuK = ball.muK;
        double inside = 0, beyond = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (inside + beyond);
            trial.run(mid, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            if (friction.zoneAt(trial.nx, trial.ny) == zone) inside = mid; else beyond = mid;
        }
        return beyond;
    }
}
