package minigolf.physics.reference;

import minigolf.course.PhysicsModel;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * The rolling models as written in docs/course-format.md ("Physics models"), for the state
 * (x, y, vx, vy):
 * <ul>
 * <li>classic: a = −g∇h − μk·g·v/|v|;</li>
 * <li>complete: a = −g∇h/D − μk·g/√D · v/√(|v|² + (∇h·v)²), D = 1 + |∇h|².</li>
 * </ul>
 * With push zones or magnets gravity's ∇h is the pull gradient P ({@link ReferenceForces#pull}).
 * The friction term is singular at v = 0; the simulator never integrates there (it stops a ball
 * whose speed falls below a tiny threshold and starts a ball from rest with {@link #fromRest}).
 */
final class RollingEquations implements DormandPrince.Rhs {
    private final Terrain terrain;
    private final ReferenceFriction friction;
    private final double g;
    private final boolean complete;
    /** A ball leaning on an obstacle does not accelerate into it. */
    private final ReferenceLean lean;
    /** Push zones and magnets (course-format.md, "Forces"). */
    private final ReferenceForces forces;
    private final double[] sample = new double[3];
    private final double[] probe = new double[3];
    private final double[] force = new double[2], pulled = new double[2];

    RollingEquations(World world, ReferenceFriction friction, ReferenceLean lean, ReferenceForces forces) {
        this.lean = lean;
        this.forces = forces;
        this.terrain = world.terrain();
        this.friction = friction;
        this.g = world.physics().gravity();
        this.complete = world.physics().model() == PhysicsModel.COMPLETE;
    }

    double gravity() {
        return g;
    }

    @Override
    public void derivative(double[] y, double[] dydt) {
        dydt[0] = y[2];
        dydt[1] = y[3];
        acceleration(y, dydt, 2);
    }

    /** Writes the acceleration at state y into out[at], out[at + 1]. */
    void acceleration(double[] y, double[] out, int at) {
        terrain.sample(y[0], y[1], sample);
        double hx = sample[1], hy = sample[2], vx = y[2], vy = y[3];
        double mu = friction.kinetic(y[0], y[1]);
        // Gravity pulls along the pull gradient (the ground's, tilted by the forces).
        double px = hx, py = hy;
        if (!forces.none()) {
            forces.held(y[0], y[1], force);
            forces.pull(hx, hy, force[0], force[1], pulled);
            px = pulled[0];
            py = pulled[1];
        }
        if (complete) {
            double d = 1 + hx * hx + hy * hy;
            double along = hx * vx + hy * vy;
            double f = mu * g / (Math.sqrt(d) * Math.sqrt(vx * vx + vy * vy + along * along));
            out[at] = -g * px / d - f * vx;
            out[at + 1] = -g * py / d - f * vy;
        } else {
            double f = mu * g / Math.hypot(vx, vy);
            out[at] = -g * px - f * vx;
            out[at + 1] = -g * py - f * vy;
        }
        lean.constrain(out, at);
    }

    /**
     * The acceleration of a ball starting from rest, the limit of the moving equations as v → 0
     * along −∇h: classic −g∇h(1 − μk/|∇h|), complete the same divided by D. Written into out[0..1].
     */
    void fromRest(double x, double y, double[] out) {
        terrain.sample(x, y, sample);
        double hx = sample[1], hy = sample[2];
        double d = 1 + hx * hx + hy * hy;
        double px = hx, py = hy;
        if (!forces.none()) {
            forces.held(x, y, force);
            forces.pull(hx, hy, force[0], force[1], pulled);
            px = pulled[0];
            py = pulled[1];
        }
        double slope = Math.hypot(px, py);
        double scale = -g * (1 - friction.kinetic(x, y) / slope);
        if (complete) scale /= d;
        out[0] = scale * px;
        out[1] = scale * py;
    }

    /** The pull gradient at rest at (x, y) (the push of the zones there), into out[0], out[1]. */
    void pullAtRest(double x, double y, double[] out) {
        terrain.sample(x, y, sample);
        if (forces.none()) {
            out[0] = sample[1];
            out[1] = sample[2];
            return;
        }
        forces.at(x, y, force);
        forces.pull(sample[1], sample[2], force[0], force[1], out);
    }

    /**
     * vᵀ·H·v, the ground's curvature along the velocity times the speed squared, with H·v from a
     * central difference of the gradient along v (the take-off criterion of docs/physics.md).
     */
    double curvatureTimesSpeedSquared(double x, double y, double vx, double vy) {
        double speed = Math.hypot(vx, vy);
        if (speed == 0) return 0;
        double ux = vx / speed, uy = vy / speed, eps = 1e-5;
        terrain.sample(x + eps * ux, y + eps * uy, probe);
        double ax = probe[1], ay = probe[2];
        terrain.sample(x - eps * ux, y - eps * uy, probe);
        double second = ((ax - probe[1]) * ux + (ay - probe[2]) * uy) / (2 * eps);
        return second * speed * speed;
    }
}
