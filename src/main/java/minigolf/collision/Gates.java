package minigolf.collision;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;

/**
 * The course's one-way gates as collision geometry for a ball of one radius (docs/course-format.md,
 * "One-way gates"). A gate is a thin vertical fence from {@code from} to {@code to}, its top a
 * wall's (the ground plus its height at both ends, straight between), reaching {@link
 * ObstacleGeometry#FOOTING} below the lowest ground along it. Its face is one-sided: a ball whose
 * whole sphere is on the {@code passTo} side and that moves against that side touches the face and
 * bounces; a ball coming from the other side passes, and so does one that has not yet got all the
 * way through when it turns back. Its two ends are posts (vertical segments) that block from both
 * sides. A ball flying over the top passes. Immutable.
 */
public final class Gates {
    /** A ball's centre at least this much less than a radius in front of the face counts as in front of it (m). */
    static final double FRONT = 1e-6;

    private final double radius;
    // Per gate: ax, ay, tx, ty (unit along), nx, ny (unit pass normal), length, bottom, topA, topB.
    private final double[] gates;
    private final double[] restitution;
    private final int[] obstacleOf;
    // Per gate: minX, minY, maxX, maxY of the fence, grown by the ball's radius.
    private final double[] boxes;
    private static final int FIELDS = 10;

    private Gates(double radius, double[] gates, double[] restitution, int[] obstacleOf) {
        this.radius = radius;
        this.gates = gates;
        this.restitution = restitution;
        this.obstacleOf = obstacleOf;
        int n = restitution.length;
        boxes = new double[4 * n];
        for (int g = 0; g < n; g++) {
            int o = FIELDS * g;
            double ax = gates[o], ay = gates[o + 1], bx = ax + gates[o + 2] * gates[o + 6], by = ay + gates[o + 3] * gates[o + 6];
            boxes[4 * g] = Math.min(ax, bx) - radius;
            boxes[4 * g + 1] = Math.min(ay, by) - radius;
            boxes[4 * g + 2] = Math.max(ax, bx) + radius;
            boxes[4 * g + 3] = Math.max(ay, by) + radius;
        }
    }

    /** The gates among the obstacles (their indices kept), or null when there are none. */
    public static Gates build(List<Obstacle> obstacles, HeightProbe ground, double ballRadius) {
        List<double[]> list = new ArrayList<>();
        List<Double> rest = new ArrayList<>();
        List<Integer> owner = new ArrayList<>();
        for (int k = 0; k < obstacles.size(); k++) {
            if (!(obstacles.get(k) instanceof Obstacle.Gate g)) continue;
            double ax = g.from().x(), ay = g.from().y(), bx = g.to().x(), by = g.to().y();
            double length = Math.hypot(bx - ax, by - ay);
            double tx = (bx - ax) / length, ty = (by - ay) / length;
            double side = g.passTo() == Obstacle.Side.LEFT ? 1 : -1;
            double lowest = Double.POSITIVE_INFINITY;
            for (int i = 0; i <= 32; i++) {
                double s = i / 32.0;
                lowest = Math.min(lowest, ground.height(ax + s * (bx - ax), ay + s * (by - ay)));
            }
            list.add(new double[] {ax, ay, tx, ty, -ty * side, tx * side, length, lowest - ObstacleGeometry.FOOTING,
                    ground.height(ax, ay) + g.height(), ground.height(bx, by) + g.height()});
            rest.add(g.restitution());
            owner.add(k);
        }
        if (list.isEmpty()) return null;
        double[] gates = new double[FIELDS * list.size()];
        double[] restitution = new double[list.size()];
        int[] obstacleOf = new int[list.size()];
        for (int i = 0; i < list.size(); i++) {
            System.arraycopy(list.get(i), 0, gates, FIELDS * i, FIELDS);
            restitution[i] = rest.get(i);
            obstacleOf[i] = owner.get(i);
        }
        return new Gates(ballRadius, gates, restitution, obstacleOf);
    }

    /** Whether a gate comes within a ball radius of the rectangle. */
    public boolean anyNear(double minX, double minY, double maxX, double maxY) {
        for (int g = 0; g < restitution.length; g++) {
            if (boxes[4 * g] <= maxX && boxes[4 * g + 2] >= minX && boxes[4 * g + 1] <= maxY && boxes[4 * g + 3] >= minY) {
                return true;
            }
        }
        return false;
    }

    /**
     * Sweeps the ball's centre from p0 to p1 against the gates; on a contact before {@code limit}
     * (a fraction of the sweep) sets {@code hit} and returns its fraction, else +infinity.
     * {@code scratch} holds at least 3 doubles.
     */
    public double sweep(double x0, double y0, double z0, double x1, double y1, double z1, double limit, Hit hit,
                        double[] scratch) {
        double r = radius;
        double minX = Math.min(x0, x1), maxX = Math.max(x0, x1), minY = Math.min(y0, y1), maxY = Math.max(y0, y1);
        double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double best = limit;
        for (int g = 0; g < restitution.length; g++) {
            if (boxes[4 * g] > maxX || boxes[4 * g + 2] < minX || boxes[4 * g + 1] > maxY || boxes[4 * g + 3] < minY) {
                continue;
            }
            int o = FIELDS * g;
            double ax = gates[o], ay = gates[o + 1], tx = gates[o + 2], ty = gates[o + 3], nx = gates[o + 4], ny = gates[o + 5];
            double span = gates[o + 6], bottom = gates[o + 7], topA = gates[o + 8], topB = gates[o + 9];
            boolean found = false;
            // The face, one-sided: only from in front (the pass side), moving against it.
            double s0 = (x0 - ax) * nx + (y0 - ay) * ny, rate = dx * nx + dy * ny;
            if (s0 >= r - FRONT && rate < -SweepTests.ALONG * length) {
                double t = s0 <= r ? 0 : (s0 - r) / -rate;
                if (t < best && t <= 1) {
                    double cx = x0 + t * dx, cy = y0 + t * dy, cz = z0 + t * dz;
                    double u = (cx - ax) * tx + (cy - ay) * ty;
                    if (u >= 0 && u <= span && cz >= bottom && cz <= topA + (topB - topA) * u / span) {
                        best = t;
                        scratch[0] = nx;
                        scratch[1] = ny;
                        scratch[2] = 0;
                        found = true;
                    }
                }
            }
            // The posts at both ends: the sides of vertical segments and their tops, from any side.
            for (int end = 0; end < 2; end++) {
                double px = ax + end * span * tx, py = ay + end * span * ty, top = end == 0 ? topA : topB;
                double t = SweepTests.segment(x0, y0, z0, dx, dy, dz, r, px, py, bottom, px, py, top, best, scratch);
                if (t < best) {
                    best = t;
                    found = true;
                }
                t = SweepTests.point(x0, y0, z0, dx, dy, dz, r, px, py, top, best, scratch);
                if (t < best) {
                    best = t;
                    found = true;
                }
            }
            if (found) hit.still(best, scratch[0], scratch[1], scratch[2], restitution[g], obstacleOf[g]);
        }
        return best < limit ? best : Double.POSITIVE_INFINITY;
    }

    public int size() {
        return restitution.length;
    }
}
