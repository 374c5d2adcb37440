package minigolf.classic;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Outlines of a set of pixels on a grid: closed rings along the pixel edges, interior on the left
 * in screen coordinates (x right, y down), so outer rings have negative signed area and holes
 * positive. Pixels that touch only at a corner belong to different rings (4-connectivity).
 * Rings are then simplified within half a pixel ({@link #simplify}), which turns the staircases
 * of diagonal and round shapes back into straight and curved lines.
 */
public final class PixelRegions {
    /** Largest distance (px) a simplified ring may stray from the pixel outline. */
    public static final double TOLERANCE = 0.5;

    private PixelRegions() {
    }

    /** A set of pixels: {@code set[x + width * y]}. */
    public record Mask(int width, int height, boolean[] set) {
        public boolean at(int x, int y) {
            return x >= 0 && y >= 0 && x < width && y < height && set[x + width * y];
        }

        public boolean isEmpty() {
            for (boolean b : set) if (b) return false;
            return true;
        }
    }

    /** The rings of a mask's outline as grid corner coordinates {x0, y0, x1, y1, ...}, collinear points removed. */
    public static List<double[]> outline(Mask m) {
        int w = m.width(), h = m.height();
        // Directed unit edges, keyed by start corner; a corner can start two (a checkerboard corner).
        Map<Integer, int[]> out = new HashMap<>();
        int stride = w + 1;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                if (!m.at(x, y)) continue;
                if (!m.at(x, y - 1)) add(out, (x + 1) + stride * y, x + stride * y);           // top edge, west
                if (!m.at(x, y + 1)) add(out, x + stride * (y + 1), (x + 1) + stride * (y + 1)); // bottom, east
                if (!m.at(x - 1, y)) add(out, x + stride * y, x + stride * (y + 1));           // left, south
                if (!m.at(x + 1, y)) add(out, (x + 1) + stride * (y + 1), (x + 1) + stride * y); // right, north
            }
        }
        List<double[]> rings = new ArrayList<>();
        while (!out.isEmpty()) {
            int start = out.keySet().iterator().next();
            List<Integer> corners = new ArrayList<>();
            int from = start, prev = -1;
            while (true) {
                int to = take(out, from, prev, stride);
                corners.add(from);
                prev = from;
                from = to;
                if (from == start && !out.containsKey(start)) break;
                if (from == start) {
                    // A checkerboard corner visited twice by different rings: close here.
                    break;
                }
            }
            rings.add(dropCollinear(corners, stride));
        }
        return rings;
    }

    private static void add(Map<Integer, int[]> out, int from, int to) {
        int[] e = out.get(from);
        if (e == null) out.put(from, new int[]{to});
        else out.put(from, new int[]{e[0], to});
    }

    /** Takes the outgoing edge at {@code from}: at a corner with two, the one turning left (staying on the same pixel). */
    private static int take(Map<Integer, int[]> out, int from, int prev, int stride) {
        int[] e = out.get(from);
        if (e.length == 1) {
            out.remove(from);
            return e[0];
        }
        int choice = 0;
        if (prev >= 0) {
            int dx = from % stride - prev % stride, dy = from / stride - prev / stride;
            int lx = dy, ly = -dx; // left of the incoming direction, screen coordinates
            for (int k = 0; k < 2; k++) {
                int ox = e[k] % stride - from % stride, oy = e[k] / stride - from / stride;
                if (ox == lx && oy == ly) choice = k;
            }
        }
        int to = e[choice];
        out.put(from, new int[]{e[1 - choice]});
        return to;
    }

    private static double[] dropCollinear(List<Integer> corners, int stride) {
        int n = corners.size();
        List<Integer> kept = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int a = corners.get((i + n - 1) % n), b = corners.get(i), c = corners.get((i + 1) % n);
            int abx = b % stride - a % stride, aby = b / stride - a / stride;
            int bcx = c % stride - b % stride, bcy = c / stride - b / stride;
            if (abx * bcy - aby * bcx != 0) kept.add(b);
        }
        double[] ring = new double[2 * kept.size()];
        for (int i = 0; i < kept.size(); i++) {
            ring[2 * i] = kept.get(i) % stride;
            ring[2 * i + 1] = kept.get(i) / stride;
        }
        return ring;
    }

    /** Twice the signed area (screen coordinates: outer rings negative). */
    public static double area2(double[] ring) {
        double s = 0;
        int n = ring.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            s += ring[2 * i] * ring[2 * j + 1] - ring[2 * j] * ring[2 * i + 1];
        }
        return s;
    }

    /**
     * The ring simplified (Douglas-Peucker) within {@code tolerance}: corners of the pixel staircase
     * that stay within the tolerance of a straight line are dropped. The result is checked: if it
     * crosses itself, the unsimplified ring is returned.
     */
    public static double[] simplify(double[] ring, double tolerance) {
        int n = ring.length / 2;
        if (n <= 4) return ring;
        // Split the closed ring at its two most distant corners (0 and the farthest from it).
        int far = 0;
        double best = -1;
        for (int i = 1; i < n; i++) {
            double d = Math.hypot(ring[2 * i] - ring[0], ring[2 * i + 1] - ring[1]);
            if (d > best) {
                best = d;
                far = i;
            }
        }
        boolean[] keep = new boolean[n];
        keep[0] = keep[far] = true;
        dp(ring, 0, far, n, tolerance, keep);
        dp(ring, far, n, n, tolerance, keep);
        int count = 0;
        for (boolean k : keep) if (k) count++;
        if (count < 3) return ring;
        double[] out = new double[2 * count];
        for (int i = 0, j = 0; i < n; i++) {
            if (!keep[i]) continue;
            out[2 * j] = ring[2 * i];
            out[2 * j + 1] = ring[2 * i + 1];
            j++;
        }
        return selfIntersects(out) || Math.signum(area2(out)) != Math.signum(area2(ring)) ? ring : out;
    }

    /** Douglas-Peucker between corners a and b (index b may be n: corner 0 again). */
    private static void dp(double[] r, int a, int b, int n, double tol, boolean[] keep) {
        if (b - a < 2) return;
        double ax = r[2 * a], ay = r[2 * a + 1], bx = r[2 * (b % n)], by = r[2 * (b % n) + 1];
        double dx = bx - ax, dy = by - ay, len = Math.hypot(dx, dy);
        int worst = -1;
        double max = tol;
        for (int i = a + 1; i < b; i++) {
            double px = r[2 * i] - ax, py = r[2 * i + 1] - ay;
            double d = len == 0 ? Math.hypot(px, py) : Math.abs(px * dy - py * dx) / len;
            if (d > max) {
                max = d;
                worst = i;
            }
        }
        if (worst < 0) return;
        keep[worst] = true;
        dp(r, a, worst, n, tol, keep);
        dp(r, worst, b, n, tol, keep);
    }

    static boolean selfIntersects(double[] ring) {
        int n = ring.length / 2;
        for (int i = 0; i < n; i++) {
            int i2 = (i + 1) % n;
            for (int j = i + 2; j < n; j++) {
                int j2 = (j + 1) % n;
                if (j2 == i) continue;
                if (cross(ring, i, i2, j, j2)) return true;
            }
        }
        return false;
    }

    private static boolean cross(double[] r, int a, int b, int c, int d) {
        double d1 = orient(r, c, d, a), d2 = orient(r, c, d, b), d3 = orient(r, a, b, c), d4 = orient(r, a, b, d);
        return (d1 > 0) != (d2 > 0) && (d3 > 0) != (d4 > 0) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
    }

    private static double orient(double[] r, int a, int b, int c) {
        return (r[2 * b] - r[2 * a]) * (r[2 * c + 1] - r[2 * a + 1]) - (r[2 * b + 1] - r[2 * a + 1]) * (r[2 * c] - r[2 * a]);
    }
}
