package minigolf.physics.reference;

import java.util.List;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.physics.World;

/**
 * Teleports for the reference (docs/course-format.md, "Teleports"), apart from the engine's: which
 * entry holds a point, whether a chord of the path enters one, and which exit comes next in the
 * stroke (in turn).
 */
final class ReferenceTeleports {
    private final List<Teleport> teleports;
    private final int[] turns;

    ReferenceTeleports(World world) {
        this.teleports = world.course().teleports();
        this.turns = new int[teleports.size()];
    }

    boolean none() {
        return teleports.isEmpty();
    }

    /** A new stroke: every teleport's next exit is its first. */
    void reset() {
        java.util.Arrays.fill(turns, 0);
    }

    int entryAt(double x, double y) {
        for (int k = 0; k < teleports.size(); k++) if (teleports.get(k).entry().contains(x, y)) return k;
        return -1;
    }

    /**
     * A time in (sa, sb] at which the ball (on the dense output, whose states at sa and sb are
     * given) is inside an entry, when the chord between them enters one; NaN otherwise.
     */
    double insideBetween(DormandPrince stepper, double sa, double sb, double[] a, double[] b) {
        if (entryAt(b[0], b[1]) >= 0) return sb;
        boolean crosses = false;
        for (Teleport t : teleports) crosses |= chordEnters(t.entry(), a[0], a[1], b[0], b[1]);
        if (!crosses) return Double.NaN;
        double[] probe = new double[4];
        for (int i = 1; i < 64; i++) {
            double tm = sa + (sb - sa) * i / 64;
            stepper.interpolate(tm, probe);
            if (entryAt(probe[0], probe[1]) >= 0) return tm;
        }
        return Double.NaN;
    }

    /** Sends the ball in entry k on: its state y is put at the exit whose turn it is, speed kept. */
    void send(int k, double[] y) {
        Teleport t = teleports.get(k);
        Teleport.Exit exit = t.exits().get(turns[k] % t.exits().size());
        turns[k]++;
        double speed = Math.hypot(y[2], y[3]);
        y[0] = exit.position().x();
        y[1] = exit.position().y();
        if (exit.directionDeg() != null) {
            double a = Math.toRadians(exit.directionDeg());
            y[2] = speed * Math.cos(a);
            y[3] = speed * Math.sin(a);
        }
    }

    /** Whether the segment a-b has a point in the shape. */
    private static boolean chordEnters(Shape shape, double ax, double ay, double bx, double by) {
        if (shape.contains(ax, ay) || shape.contains(bx, by)) return true;
        if (shape instanceof Shape.Circle c) {
            double dx = bx - ax, dy = by - ay, length2 = dx * dx + dy * dy;
            double s = length2 == 0 ? 0 : Math.max(0, Math.min(1, ((c.center().x() - ax) * dx + (c.center().y() - ay) * dy) / length2));
            return Math.hypot(ax + s * dx - c.center().x(), ay + s * dy - c.center().y()) <= c.radius();
        }
        List<Vec2> corners;
        if (shape instanceof Shape.Rect r) {
            corners = List.of(r.min(), new Vec2(r.max().x(), r.min().y()), r.max(), new Vec2(r.min().x(), r.max().y()));
        } else {
            corners = ((Shape.Polygon) shape).points();
        }
        for (int i = 0; i < corners.size(); i++) {
            Vec2 p = corners.get(i), q = corners.get((i + 1) % corners.size());
            if (segmentsCross(ax, ay, bx, by, p.x(), p.y(), q.x(), q.y())) return true;
        }
        return false;
    }

    private static boolean segmentsCross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
        double d1 = side(cx, cy, dx, dy, ax, ay), d2 = side(cx, cy, dx, dy, bx, by);
        double d3 = side(ax, ay, bx, by, cx, cy), d4 = side(ax, ay, bx, by, dx, dy);
        return d1 * d2 <= 0 && d3 * d4 <= 0;
    }

    private static double side(double px, double py, double qx, double qy, double x, double y) {
        return (qx - px) * (y - py) - (qy - py) * (x - px);
    }
}
