package minigolf.physics.reference;

import java.util.List;
import minigolf.course.Magnet;
import minigolf.course.PhysicsModel;
import minigolf.course.PushZone;
import minigolf.physics.World;

/**
 * Push zones and magnets for the reference, from docs/course-format.md ("Push zones", "Magnets",
 * "Forces"), written apart from the engine's ForceField. The push is held fixed over a stretch of
 * path, as {@link ReferenceFriction} holds a zone: the simulator restarts the integration where
 * the push under the ball changes (an event), so the force never jumps inside a step. A magnet's
 * pull is smooth and evaluated where the ball is.
 */
final class ReferenceForces {
    private final List<PushZone> pushes;
    private final List<Magnet> magnets;
    private final double g;
    private final boolean complete;
    private double heldX, heldY;

    ReferenceForces(World world) {
        this.pushes = world.course().pushZones();
        this.magnets = world.course().magnets();
        this.g = world.physics().gravity();
        this.complete = world.physics().model() == PhysicsModel.COMPLETE;
    }

    boolean none() {
        return pushes.isEmpty() && magnets.isEmpty();
    }

    boolean hasPushes() {
        return !pushes.isEmpty();
    }

    /** Holds the push of the point (x, y) for the integration that follows. */
    void holdPushAt(double x, double y) {
        heldX = pushX(x, y);
        heldY = pushY(x, y);
    }

    /** Whether the push at (x, y) is not the one held: the ball has crossed a push zone's edge. */
    boolean pushChangedAt(double x, double y) {
        return pushX(x, y) != heldX || pushY(x, y) != heldY;
    }

    private double pushX(double x, double y) {
        double sum = 0;
        for (PushZone z : pushes) if (z.shape().contains(x, y)) sum += z.push().x();
        return sum;
    }

    private double pushY(double x, double y) {
        double sum = 0;
        for (PushZone z : pushes) if (z.shape().contains(x, y)) sum += z.push().y();
        return sum;
    }

    /** The force on the ball at (x, y): the held push and the magnets' pull, into out[0], out[1]. */
    void held(double x, double y, double[] out) {
        out[0] = heldX;
        out[1] = heldY;
        addMagnets(x, y, out);
    }

    /** The force at (x, y) with the push of the zones there (for a ball at rest). */
    void at(double x, double y, double[] out) {
        out[0] = pushX(x, y);
        out[1] = pushY(x, y);
        addMagnets(x, y, out);
    }

    /** Each magnet pulls with (27/4) s u (1 - u)^2 towards its centre (u = d/R < 1). */
    private void addMagnets(double x, double y, double[] out) {
        for (Magnet m : magnets) {
            double ex = m.position().x() - x, ey = m.position().y() - y;
            double d = Math.hypot(ex, ey), u = d / m.radius();
            if (u >= 1 || d == 0) continue;
            double magnitude = m.strength() * 27.0 / 4.0 * u * (1 - u) * (1 - u);
            out[0] += magnitude * ex / d;
            out[1] += magnitude * ey / d;
        }
    }

    /**
     * The pull gradient P for ground gradient (hx, hy) and force f (course-format.md, "Forces"):
     * classic ∇h − f/g; complete ∇h(1 + ∇h·f/g) − D f/g with D = 1 + |∇h|². Into out[0], out[1].
     */
    void pull(double hx, double hy, double fx, double fy, double[] out) {
        if (!complete) {
            out[0] = hx - fx / g;
            out[1] = hy - fy / g;
            return;
        }
        double d = 1 + hx * hx + hy * hy, grade = (hx * fx + hy * fy) / g;
        out[0] = hx + hx * grade - d * fx / g;
        out[1] = hy + hy * grade - d * fy / g;
    }
}
