package minigolf.physics;

import minigolf.course.Shape;
import minigolf.course.Vec2;

/** Where a straight segment first enters a course shape (rectangle, circle, polygon, cells). */
final class ShapeCrossing {
    private ShapeCrossing() {
    }

    /**
     * The first fraction in [0, 1] of the segment from a to b that lies in the shape (0 if a does),
     * or +infinity if none does.
     */
    static double firstEntry(Shape shape, double ax, double ay, double bx, double by) {
        if (shape.contains(ax, ay)) return 0;
        double dx = bx - ax, dy = by - ay;
        if (shape instanceof Shape.Rect r) {
            double lo = 0, hi = 1;
            double[] range = {lo, hi};
            if (!clip(ax, dx, r.min().x(), r.max().x(), range) || !clip(ay, dy, r.min().y(), r.max().y(), range)) {
                return Double.POSITIVE_INFINITY;
            }
            return range[0];
        }
        if (shape instanceof Shape.Circle c) {
            double mx = ax - c.center().x(), my = ay - c.center().y(), rr = c.radius();
            double a = dx * dx + dy * dy, b = mx * dx + my * dy, k = mx * mx + my * my - rr * rr;
            double disc = b * b - a * k;
            if (a == 0 || disc < 0 || b >= 0) return Double.POSITIVE_INFINITY;
            double t = k / (-b + Math.sqrt(disc));
            return t <= 1 ? t : Double.POSITIVE_INFINITY;
        }
        if (shape instanceof Shape.Cells c) return firstCell(c, ax, ay, dx, dy);
        // A polygon: the first crossing of an edge (the segment starts outside).
        double best = Double.POSITIVE_INFINITY;
        var points = ((Shape.Polygon) shape).points();
        int n = points.size();
        for (int i = 0, j = n - 1; i < n; j = i++) {
            Vec2 p = points.get(j), q = points.get(i);
            double ex = q.x() - p.x(), ey = q.y() - p.y();
            double denominator = dx * ey - dy * ex;
            if (denominator == 0) continue;
            double wx = p.x() - ax, wy = p.y() - ay;
            double t = (wx * ey - wy * ex) / denominator;
            double u = (wx * dy - wy * dx) / denominator;
            if (t >= 0 && t <= 1 && u >= 0 && u <= 1 && t < best) best = t;
        }
        return best;
    }

    /**
     * The first set cell the segment a + t d (t in [0, 1], a outside the shape) enters: it walks the
     * grid cell by cell along the segment (Amanatides and Woo), so it is exact whatever the outline.
     */
    private static double firstCell(Shape.Cells c, double ax, double ay, double dx, double dy) {
        double s = c.size();
        // In cell units, clipped to the grid.
        double u = (ax - c.origin().x()) / s, v = (ay - c.origin().y()) / s, du = dx / s, dv = dy / s;
        double[] range = {0, 1};
        if (!clip(u, du, 0, c.columns(), range) || !clip(v, dv, 0, c.rows(), range)) return Double.POSITIVE_INFINITY;
        double t = range[0], end = range[1];
        int i = Math.min(c.columns() - 1, (int) Math.floor(u + t * du));
        int j = Math.min(c.rows() - 1, (int) Math.floor(v + t * dv));
        int stepI = du > 0 ? 1 : -1, stepJ = dv > 0 ? 1 : -1;
        double nextI = du != 0 ? ((du > 0 ? i + 1 : i) - u) / du : Double.POSITIVE_INFINITY;
        double nextJ = dv != 0 ? ((dv > 0 ? j + 1 : j) - v) / dv : Double.POSITIVE_INFINITY;
        double deltaI = du != 0 ? 1 / Math.abs(du) : Double.POSITIVE_INFINITY, deltaJ = dv != 0 ? 1 / Math.abs(dv) : Double.POSITIVE_INFINITY;
        while (t <= end) {
            if (c.cell(i, j)) return t;
            if (nextI < nextJ) {
                t = nextI;
                nextI += deltaI;
                i += stepI;
            } else {
                t = nextJ;
                nextJ += deltaJ;
                j += stepJ;
            }
            if (i < 0 || j < 0 || i >= c.columns() || j >= c.rows()) break;
        }
        return Double.POSITIVE_INFINITY;
    }

    /** Clips the fraction range to where a + t d lies in [lo, hi] on one axis; false if empty. */
    private static boolean clip(double a, double d, double lo, double hi, double[] range) {
        if (d == 0) return a >= lo && a <= hi;
        double t0 = (lo - a) / d, t1 = (hi - a) / d;
        if (t0 > t1) {
            double swap = t0;
            t0 = t1;
            t1 = swap;
        }
        range[0] = Math.max(range[0], t0);
        range[1] = Math.min(range[1], t1);
        return range[0] <= range[1];
    }
}
