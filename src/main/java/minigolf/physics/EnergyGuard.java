package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * Energy never grows (docs/course-format.md, rule 3): a committed rolling step must have lost at
 * least half the least friction work over its chord. Smooth ground never comes near that; a step
 * across a crease (a V-shaped valley's floor, a cone's tip), where the start's slope pumps energy
 * in, does. Then the speed is cut to what the energy allows, or, where even the end's height is
 * out of reach, the step is cut where the energy runs out and the ball is momentarily at rest there.
 */
final class EnergyGuard {
    private final BallState ball;
    private final RollingTrial trial;
    private final StrokeReports reports;
    private final Terrain terrain;
    private final double gravity;
    private final boolean complete;
    /** Push zones and magnets, whose work counts as energy gained; null without them. */
    private final ForceField forces;
    private final double[] push = new double[2];

    EnergyGuard(BallState ball, RollingTrial trial, StrokeReports reports, Terrain terrain, double gravity,
                boolean complete, ForceField forces) {
        this.forces = forces;
        this.ball = ball;
        this.trial = trial;
        this.reports = reports;
        this.terrain = terrain;
        this.gravity = gravity;
        this.complete = complete;
    }

    /** E = |v|^2/2 + g h per unit mass; the complete model counts the vertical speed grad h . v too. */
    private double energy(double ux, double uy, double height, double gx, double gy) {
        double along = complete ? gx * ux + gy * uy : 0;
        return 0.5 * (ux * ux + uy * uy + along * along) + gravity * height;
    }

    /** Half the least friction work over a chord of this length from the step's start. */
    private double halfFrictionWork(double chord) {
        double work = ball.pMuK * gravity * chord;
        return 0.5 * (complete ? work / Math.sqrt(1 + ball.phx * ball.phx + ball.phy * ball.phy) : work);
    }

    /**
     * The work per unit mass of the push zones and magnets from the step's start to (x, y): the
     * start's push (a step never crosses a push zone's edge) along the chord, and the magnets'
     * potential difference. 0 without them.
     */
    private double forceWork(double x, double y) {
        if (forces == null) return 0;
        BallState b = ball;
        if (!forces.hasMagnets()) {
            // The force at the step's start is its push alone.
            return b.pfx * (x - b.px) + b.pfy * (y - b.py);
        }
        forces.push(b.px, b.py, push);
        return push[0] * (x - b.px) + push[1] * (y - b.py) + forces.magnetPotential(b.px, b.py) - forces.magnetPotential(x, y);
    }

    /**
     * Checks the step just committed (from the ball's step start to its state). Returns true when
     * it dissipates enough; false when it has rewritten the step (and reported the new state).
     */
    boolean dissipates(RollingStep.Kind kind, double a1x, double a1y) {
        BallState b = ball;
        double e0 = energy(b.pvx, b.pvy, b.ph, b.phx, b.phy);
        double cx = b.x - b.px, cy = b.y - b.py;
        double allowed = e0 - halfFrictionWork(Math.sqrt(cx * cx + cy * cy));
        if (forces != null) allowed += forceWork(b.x, b.y);
        double slack = 1e-9 * (Math.abs(e0) + 1);
        double e1 = energy(b.vx, b.vy, b.h, b.hx, b.hy);
        if (e1 <= allowed + slack) return true;
        double kinetic = e1 - gravity * b.h;
        double room = allowed - gravity * b.h;
        if (room > 0 && kinetic > 0) {
            double keep = Math.sqrt(room / kinetic);
            b.vx *= keep;
            b.vy *= keep;
            reports.state();
            return false;
        }
        // The end is higher than the energy reaches: go back and stop where it runs out.
        double spent = b.pieceTime;
        b.backToStepStart();
        double reach = 0, beyond = spent;
        for (int k = 0; k < StepLocator.LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (reach + beyond);
            trial.run(mid, kind, a1x, a1y);
            double need = gravity * terrain.height(trial.nx, trial.ny)
                    + halfFrictionWork(Math.hypot(trial.nx - b.x, trial.ny - b.y));
            if (forces != null) need -= forceWork(trial.nx, trial.ny);
            if (need <= e0) reach = mid; else beyond = mid;
        }
        trial.run(reach, kind, a1x, a1y);
        b.x = trial.nx;
        b.y = trial.ny;
        b.vx = 0;
        b.vy = 0;
        b.t = b.pt + reach;
        b.pieceTime = reach;
        b.sampleGround();
        b.z = b.h;
        reports.state();
        b.resume = reach < spent;
        return false;
    }
}
