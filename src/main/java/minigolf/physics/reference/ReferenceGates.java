package minigolf.physics.reference;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Obstacle;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * One-way gates for the reference (docs/course-format.md, "One-way gates"), apart from the engine's
 * collision code: whether a straight chord of the ball's centre touches a gate's face from the pass
 * side, or one of its end posts, and the contact's normal.
 */
final class ReferenceGates {
    /** A centre this much less than a radius in front of the face still counts as in front (m). */
    private static final double FRONT = 1e-6;
    private static final double FOOTING = 1.0;

    private record Gate(double ax, double ay, double bx, double by, double nx, double ny, double bottom, double topA,
                        double topB, double restitution) {
    }

    private final List<Gate> gates = new ArrayList<>();
    private final double r;

    /** The contact found by the last {@link #touches}: its normal and restitution. */
    double nx, ny, nz, restitution;

    ReferenceGates(World world) {
        this.r = world.physics().ballRadius();
        Terrain terrain = world.terrain();
        for (Obstacle o : world.course().obstacles()) {
            if (!(o instanceof Obstacle.Gate g)) continue;
            double ax = g.from().x(), ay = g.from().y(), bx = g.to().x(), by = g.to().y();
            double lowest = Double.POSITIVE_INFINITY;
            for (int i = 0; i <= 32; i++) {
                lowest = Math.min(lowest, terrain.height(ax + (bx - ax) * i / 32, ay + (by - ay) * i / 32));
            }
            var n = g.passNormal();
            gates.add(new Gate(ax, ay, bx, by, n.x(), n.y(), lowest - FOOTING, terrain.height(ax, ay) + g.height(),
                    terrain.height(bx, by) + g.height(), g.restitution()));
        }
    }

    boolean none() {
        return gates.isEmpty();
    }

    /** Whether the centre's chord from p to q touches a gate (the face from its pass side, or a post). */
    boolean touches(double px, double py, double pz, double qx, double qy, double qz) {
        boolean found = false;
        for (Gate g : gates) {
            double front0 = (px - g.ax) * g.nx + (py - g.ay) * g.ny;
            double front1 = (qx - g.ax) * g.nx + (qy - g.ay) * g.ny;
            if (front0 >= r - FRONT && front1 < front0 && front1 <= r) {
                double f = front0 <= r ? 0 : (front0 - r) / (front0 - front1);
                double cx = px + f * (qx - px), cy = py + f * (qy - py), cz = pz + f * (qz - pz);
                double lx = g.bx - g.ax, ly = g.by - g.ay, length2 = lx * lx + ly * ly;
                double along = ((cx - g.ax) * lx + (cy - g.ay) * ly) / length2;
                if (along >= 0 && along <= 1 && cz >= g.bottom && cz <= g.topA + along * (g.topB - g.topA)) {
                    nx = g.nx;
                    ny = g.ny;
                    nz = 0;
                    restitution = g.restitution;
                    found = true;
                    continue;
                }
            }
            if (post(g.ax, g.ay, g.bottom, g.topA, px, py, pz, qx, qy, qz) || post(g.bx, g.by, g.bottom, g.topB, px, py, pz, qx, qy, qz)) {
                restitution = g.restitution;
                found = true;
            }
        }
        return found;
    }

    /**
     * Whether the chord p-q comes within r of the vertical post at (x, y) from bottom to top; if so
     * the normal from the post's nearest point to the chord's nearest point.
     */
    private boolean post(double x, double y, double bottom, double top, double px, double py, double pz,
                         double qx, double qy, double qz) {
        // The nearest points of the two segments, by a fine search on the chord and the exact one on the post.
        double best = Double.POSITIVE_INFINITY, bx = 0, by = 0, bz = 0, bpz = 0;
        int samples = 64;
        for (int i = 0; i <= samples; i++) {
            double s = (double) i / samples;
            double cx = px + s * (qx - px), cy = py + s * (qy - py), cz = pz + s * (qz - pz);
            double z = Math.max(bottom, Math.min(top, cz));
            double d = Math.sqrt((cx - x) * (cx - x) + (cy - y) * (cy - y) + (cz - z) * (cz - z));
            if (d < best) {
                best = d;
                bx = cx;
                by = cy;
                bz = cz;
                bpz = z;
            }
        }
        if (best > r) {
            // The coarse search can miss a grazing minimum between samples: the exact distance from the
            // post's axis to the chord in the plane bounds it from below.
            double dx = qx - px, dy = qy - py, length2 = dx * dx + dy * dy;
            double s = length2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - px) * dx + (y - py) * dy) / length2));
            double cx = px + s * dx, cy = py + s * dy, cz = pz + s * (qz - pz);
            double z = Math.max(bottom, Math.min(top, cz));
            double d = Math.sqrt((cx - x) * (cx - x) + (cy - y) * (cy - y) + (cz - z) * (cz - z));
            if (d > r) return false;
            best = d;
            bx = cx;
            by = cy;
            bz = cz;
            bpz = z;
        }
        double length = Math.max(best, 1e-300);
        nx = (bx - x) / length;
        ny = (by - y) / length;
        nz = (bz - bpz) / length;
        return true;
    }
}
