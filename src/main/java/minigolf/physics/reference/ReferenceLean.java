package minigolf.physics.reference;

import minigolf.collision.CollisionScene;
import minigolf.collision.Hit;
import minigolf.course.PhysicsModel;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * Rolling along an obstacle, for the reference, as docs/physics.md states it: after a contact
 * that keeps the ball on the ground, with c the contact normal's horizontal direction (normals
 * within 45° of horizontal only), w = v·c its speed away from the obstacle and
 * p = g·(∇h·c)/D the ground's pull towards it (D = 1 + |∇h|² in the complete model, 1 in the
 * classic), the ball settles when p &gt; 0 and w²/(2p) &lt; 1 mm: w is removed and, while it leans,
 * any acceleration into the obstacle (a·c &lt; 0) is taken by it. It leaves the obstacle at the
 * first moment p ≤ 0, or the ball moved 1 mm along −c no longer touches the obstacle.
 */
final class ReferenceLean {
    private static final double REACH = 1e-3;
    /** A settled ball is moved this far off the obstacle so that rolling along it touches nothing. */
    private static final double CLEARANCE = 1e-9;

    private final CollisionScene scene;
    private final Terrain terrain;
    private final double g, radius;
    private final boolean complete;
    private final Hit hit = new Hit();
    private final double[] scratch = new double[3], sample = new double[3];

    private boolean on;
    private double cx, cy;
    /** Push zones and magnets tilt the pull (course-format.md, "Forces"); gates can be leant on too. */
    private ReferenceForces forces;
    private ReferenceGates gates;
    private final double[] force = new double[2], pulled = new double[2];

    /** The forces and the gates, once they exist (the simulator builds them after this). */
    void with(ReferenceForces forces, ReferenceGates gates) {
        this.forces = forces;
        this.gates = gates;
    }

    ReferenceLean(World world) {
        this.scene = world.obstacles();
        this.terrain = world.terrain();
        this.g = world.physics().gravity();
        this.radius = world.physics().ballRadius();
        this.complete = world.physics().model() == PhysicsModel.COMPLETE;
    }

    boolean on() {
        return on;
    }

    void off() {
        on = false;
    }

    /**
     * The contact with normal n has left the rolling state y on the ground: settles the ball
     * against the obstacle (y's velocity and position changed) or leaves it free.
     */
    void afterContact(double[] y, double nx, double ny, double nz) {
        on = false;
        double flat = Math.hypot(nx, ny);
        if (flat == 0 || nz * nz >= 0.5) return;
        double ux = nx / flat, uy = ny / flat;
        double pull = pullAt(y[0], y[1], ux, uy);
        double w = y[2] * ux + y[3] * uy;
        if (pull <= 0 || w * w >= 2 * pull * REACH) return;
        cx = ux;
        cy = uy;
        on = true;
        y[2] -= w * cx;
        y[3] -= w * cy;
        y[0] += CLEARANCE * cx;
        y[1] += CLEARANCE * cy;
    }

    /** Removes from a = (out[at], out[at+1]) its part into the obstacle while the ball leans on it. */
    void constrain(double[] out, int at) {
        if (!on) return;
        double into = out[at] * cx + out[at + 1] * cy;
        if (into < 0) {
            out[at] -= into * cx;
            out[at + 1] -= into * cy;
        }
    }

    /** Whether a leaning ball at (x, y) leaves its obstacle there: no pull towards it, or out of reach. */
    boolean leavesAt(double x, double y) {
        return on && (pullAt(x, y, cx, cy) <= 0 || !reaches(x, y));
    }

    private double pullAt(double x, double y, double ux, double uy) {
        terrain.sample(x, y, sample);
        double hx = sample[1], hy = sample[2], px = hx, py = hy;
        if (forces != null && !forces.none()) {
            forces.at(x, y, force);
            forces.pull(hx, hy, force[0], force[1], pulled);
            px = pulled[0];
            py = pulled[1];
        }
        double p = g * (px * ux + py * uy);
        return complete ? p / (1 + hx * hx + hy * hy) : p;
    }

    private boolean reaches(double x, double y) {
        double tx = x - REACH * cx, ty = y - REACH * cy;
        return touchesStill(x, y, tx, ty);
    }

    /** Whether the ball moved from (x, y) to (tx, ty) on the ground touches a still obstacle or a gate. */
    private boolean touchesStill(double x, double y, double tx, double ty) {
        double z0 = terrain.height(x, y) + radius, z1 = terrain.height(tx, ty) + radius;
        if (scene != null && scene.sweep(x, y, z0, tx, ty, z1, hit, scratch)) return true;
        return gates != null && !gates.none() && gates.touches(x, y, z0, tx, ty, z1);
    }

    /**
     * Rule 2's obstacle clause for a ball at rest at (x, y) on slope (hx, hy): moved 1 mm down
     * the slope it would touch an obstacle, which takes the push.
     */
    boolean leansAtRest(double x, double y, double hx, double hy) {
        if ((scene == null || scene.isEmpty()) && (gates == null || gates.none())) return false;
        double slope = Math.hypot(hx, hy);
        if (slope == 0) return false;
        double tx = x - REACH * hx / slope, ty = y - REACH * hy / slope;
        return touchesStill(x, y, tx, ty);
    }
}
