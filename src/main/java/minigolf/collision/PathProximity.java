package minigolf.collision;

import java.util.Arrays;

/**
 * Cheap "may anything be touched here?" answers about a scene's still shapes, asked before the
 * sweeps of a path so that a path far from every shape costs no sweep. Each answer is exact as a
 * "no": it never hides a contact that a sweep along the path would find. Kept apart from the
 * sweep ({@link CollisionScene}) because the physics asks these questions more often than it
 * sweeps, and they test outlines in the plane rather than the swept sphere.
 */
final class PathProximity {
    private final ShapeGrid grid;
    private final double radius;
    private final double[] triangles, cylinders, boxes;
    private final int triangleCount;

    /** Over the scene's shapes: triangles (12 doubles each), then cylinders (5); one box (6) per shape. */
    PathProximity(ShapeGrid grid, double radius, double[] triangles, double[] cylinders, double[] boxes) {
        this.grid = grid;
        this.radius = radius;
        this.triangles = triangles;
        this.cylinders = cylinders;
        this.boxes = boxes;
        this.triangleCount = triangles.length / 12;
        int runs = grid.runStart.length - 1;
        hullStart = new int[runs];
        hullSize = new byte[runs];
        // Hulls cost time and memory at load: a budget of 4 points a triangle holds every run's hull
        // on the bundled courses (about 1.6 a triangle) and for 2,500 boxes drawn tile by tile (4.2),
        // but half of them for 2,500 models 100 m wide (7.6: each triangle listed in 7 cells); a run
        // past it is tested shape by shape.
        int budget = 4 * triangleCount + 10_000;
        double[] hull = new double[2 * (budget + 3 * ShapeGrid.RUN_LENGTH)];
        int used = 0;
        double[] points = new double[2 * 3 * ShapeGrid.RUN_LENGTH];
        int[] order = new int[3 * ShapeGrid.RUN_LENGTH], chain = new int[6 * ShapeGrid.RUN_LENGTH + 1];
        // A long wall is listed in every cell along it with the same triangles: its run in each of
        // those cells shares one hull, found through the last run that began with the same shape.
        int[] lastRunOf = new int[triangleCount];
        Arrays.fill(lastRunOf, -1);
        for (int q = 0; q < runs; q++) {
            int first = grid.runStart[q], end = grid.runStart[q + 1];
            // Runs of one obstacle: all triangles or a single cylinder.
            if (grid.cellItems[first] >= triangleCount) continue;
            int lead = grid.cellItems[first], same = lastRunOf[lead];
            if (same >= 0 && sameItems(grid, same, q)) {
                hullStart[q] = hullStart[same];
                hullSize[q] = hullSize[same];
                continue;
            }
            if (used > budget) continue;
            int n = 0;
            for (int k = first; k < end; k++) {
                int o = 12 * grid.cellItems[k];
                for (int v = 0; v < 3; v++) {
                    points[n++] = triangles[o + 3 * v];
                    points[n++] = triangles[o + 3 * v + 1];
                }
            }
            int size = convexHull(points, n / 2, hull, 2 * used, order, chain);
            hullStart[q] = used;
            hullSize[q] = (byte) size;
            used += size;
            lastRunOf[lead] = q;
        }
        hulls = Arrays.copyOf(hull, 2 * used);
    }

    /** The hull points stored, and those the runs list (more where runs share a hull). */
    long[] hullPoints() {
        long listed = 0;
        for (byte size : hullSize) listed += size;
        return new long[] {hulls.length / 2, listed};
    }

    /** Whether runs a and b list the same shapes in the same order. */
    private static boolean sameItems(ShapeGrid grid, int a, int b) {
        int fromA = grid.runStart[a], fromB = grid.runStart[b], length = grid.runStart[b + 1] - fromB;
        if (grid.runStart[a + 1] - fromA != length) return false;
        for (int k = 0; k < length; k++) {
            if (grid.cellItems[fromA + k] != grid.cellItems[fromB + k]) return false;
        }
        return true;
    }

    /**
     * Each run of triangles' outlines seen from above as one convex polygon, counter-clockwise:
     * run q's hullSize[q] points (at most 3 {@link ShapeGrid#RUN_LENGTH}, so a byte holds it) are
     * hulls[2 hullStart[q] ..) (none for a cylinder's run). A wall's or a box's 12 triangles all lie
     * in its footprint, so 1 test serves for 12.
     */
    private final int[] hullStart;
    private final byte[] hullSize;
    private final double[] hulls;

    /**
     * Writes the convex hull of the n points (x, y pairs in p) counter-clockwise into out from
     * offset at, without collinear points (Andrew's monotone chain); returns its number of points.
     */
    static int convexHull(double[] p, int n, double[] out, int at) {
        return convexHull(p, n, out, at, new int[n], new int[2 * n + 1]);
    }

    /** As above, with scratch arrays of at least n (order) and 2n + 1 (chain) entries. */
    private static int convexHull(double[] p, int n, double[] out, int at, int[] order, int[] chain) {
        // Akl-Toussaint: a point strictly inside the quadrilateral of the leftmost, lowest,
        // rightmost and highest points is no corner of the hull; a model's run drops most of its 48.
        int left = 0, low = 0, right = 0, high = 0;
        for (int i = 1; i < n; i++) {
            if (after(p, left, i)) left = i;
            if (after(p, i, right)) right = i;
            if (p[2 * i + 1] < p[2 * low + 1]) low = i;
            if (p[2 * i + 1] > p[2 * high + 1]) high = i;
        }
        int m = 0;
        for (int i = 0; i < n; i++) {
            boolean inside = cross(p, left, low, i) > 0 && cross(p, low, right, i) > 0
                    && cross(p, right, high, i) > 0 && cross(p, high, left, i) > 0;
            if (inside) continue;
            // Insertion sort by x, then y (a run has at most 48 points; no boxing), each point once:
            // a box's 36 corners of faces are its 4 corners.
            int k = m;
            while (k > 0 && after(p, order[k - 1], i)) k--;
            if (k > 0 && p[2 * order[k - 1]] == p[2 * i] && p[2 * order[k - 1] + 1] == p[2 * i + 1]) continue;
            System.arraycopy(order, k, order, k + 1, m - k);
            order[k] = i;
            m++;
        }
        n = m;
        int h = 0;
        for (int r = 0; r < n; r++) {
            int i = order[r];
            while (h >= 2 && cross(p, chain[h - 2], chain[h - 1], i) <= 0) h--;
            chain[h++] = i;
        }
        int lower = h + 1;
        for (int r = n - 2; r >= 0; r--) {
            int i = order[r];
            while (h >= lower && cross(p, chain[h - 2], chain[h - 1], i) <= 0) h--;
            chain[h++] = i;
        }
        h--; // the last point is the first again
        // All the points one: the chain holds it twice.
        if (h < 1 || (h == 2 && p[2 * chain[0]] == p[2 * chain[1]] && p[2 * chain[0] + 1] == p[2 * chain[1] + 1])) h = 1;
        for (int k = 0; k < h; k++) {
            out[at + 2 * k] = p[2 * chain[k]];
            out[at + 2 * k + 1] = p[2 * chain[k] + 1];
        }
        return h;
    }

    /** Whether point a of p sorts after point b: by x, then y (equal points keep their order). */
    private static boolean after(double[] p, int a, int b) {
        return p[2 * a] != p[2 * b] ? p[2 * a] > p[2 * b] : p[2 * a + 1] > p[2 * b + 1];
    }

    /** The z of (b - a) x (c - a) for points a, b, c of p. */
    private static double cross(double[] p, int a, int b, int c) {
        return (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
    }

    /**
     * Whether the convex polygon of hull points [from, to) meets the box round the segment (centre
     * m, unit axis u, half-lengths {@code along} u and {@code across} perpendicular to it): no
     * separating axis among the box's two and the polygon's edge normals (a polygon of 2 points
     * is a segment, of 1 a point). A nanometre to spare, so that it says "near" wherever
     * {@link #outlineNear} would for a triangle inside it.
     */
    private boolean hullNear(int from, int to, double mx, double my, double ux, double uy, double along, double across) {
        double[] h = hulls;
        double lowU = Double.POSITIVE_INFINITY, highU = Double.NEGATIVE_INFINITY;
        double lowN = Double.POSITIVE_INFINITY, highN = Double.NEGATIVE_INFINITY;
        for (int k = from; k < to; k++) {
            double px = h[2 * k] - mx, py = h[2 * k + 1] - my;
            double pu = px * ux + py * uy, pn = py * ux - px * uy;
            lowU = Math.min(lowU, pu);
            highU = Math.max(highU, pu);
            lowN = Math.min(lowN, pn);
            highN = Math.max(highN, pn);
        }
        if (lowU > along + 1e-9 || highU < -along - 1e-9 || lowN > across + 1e-9 || highN < -across - 1e-9) return false;
        for (int k = from; k < to && to - from > 1; k++) {
            int next = k + 1 < to ? k + 1 : from;
            double ax = h[2 * k], ay = h[2 * k + 1];
            // The edge's outward normal (counter-clockwise polygon): every point lies on its inner side.
            double nx = h[2 * next + 1] - ay, ny = ax - h[2 * next];
            double half = along * Math.abs(ux * nx + uy * ny) + across * Math.abs(uy * nx - ux * ny);
            double centre = (mx - ax) * nx + (my - ay) * ny;
            if (centre > half + 1e-9 * (Math.abs(nx) + Math.abs(ny))) return false;
        }
        return true;
    }

    /** As {@link CollisionScene#anyShapeNear}. */
    boolean anyShapeNear(double minX, double minY, double maxX, double maxY) {
        double r = radius;
        return listedShapeNear(grid.column(minX), grid.column(maxX), grid.row(minY), grid.row(maxY),
                minX - r, minY - r, maxX + r, maxY + r, false, 0, 0, 0, 0, 0);
    }

    /** As {@link CollisionScene#anyShapeNearPath}. */
    boolean anyShapeNearPath(double x0, double y0, double x1, double y1, double margin) {
        double reach = margin + radius + 1e-9;
        double loX = Math.min(x0, x1) - reach, hiX = Math.max(x0, x1) + reach;
        double loY = Math.min(y0, y1) - reach, hiY = Math.max(y0, y1) + reach;
        return listedShapeNear(grid.column(loX + radius), grid.column(hiX - radius), grid.row(loY + radius),
                grid.row(hiY - radius), loX, loY, hiX, hiY, true, x0, y0, x1, y1, reach);
    }

    /**
     * Whether a shape listed in the cells [i0, i1] x [j0, j1] has its box in the rectangle
     * [loX, hiX] x [loY, hiY] and, with {@code outlines}, its outline within reach of the segment
     * from (x0, y0) to (x1, y1).
     */
    private boolean listedShapeNear(int i0, int i1, int j0, int j1, double loX, double loY, double hiX, double hiY,
                                    boolean outlines, double x0, double y0, double x1, double y1, double reach) {
        // The box round the segment: centre, unit axis u (along), half-length along it.
        double dx = x1 - x0, dy = y1 - y0, length = Math.sqrt(dx * dx + dy * dy);
        double ux = length > 0 ? dx / length : 1, uy = length > 0 ? dy / length : 0;
        double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1), along = 0.5 * length + reach;
        ShapeGrid g = grid;
        int columns = g.columns;
        int[] cellRuns = g.cellRuns, runStart = g.runStart, cellItems = g.cellItems;
        float[] runBox = g.runBoxes;
        double[] boxes = this.boxes;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                int c = j * columns + i;
                for (int q = cellRuns[c], last = cellRuns[c + 1]; q < last; q++) {
                    int rb = 6 * q;
                    if (runBox[rb] > hiX || runBox[rb + 3] < loX || runBox[rb + 1] > hiY || runBox[rb + 4] < loY) continue;
                    if (outlines && hullSize[q] > 0) {
                        // A run of triangles: their outlines' hull decides for all of them at once.
                        int from = hullStart[q];
                        if (hullNear(from, from + hullSize[q], mx, my, ux, uy, along, reach)) return true;
                        continue;
                    }
                    for (int k = runStart[q], end = runStart[q + 1]; k < end; k++) {
                        int s = cellItems[k];
                        int b = 6 * s;
                        if (boxes[b] > hiX || boxes[b + 3] < loX || boxes[b + 1] > hiY || boxes[b + 4] < loY) continue;
                        if (!outlines || (s < triangleCount ? outlineNear(12 * s, mx, my, ux, uy, along, reach)
                                : circleNear(5 * (s - triangleCount), x0, y0, dx, dy, reach))) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    /**
     * Whether the triangle at offset o, seen from above, meets the box with centre m, unit axis u,
     * half-lengths {@code along} u and {@code across} perpendicular to it: no separating axis among
     * the box's two and the outline's three edge normals (a triangle seen edge-on is a segment:
     * its normals coincide; a zero edge separates nothing).
     */
    private boolean outlineNear(int o, double mx, double my, double ux, double uy, double along, double across) {
        double[] t = triangles;
        double ax = t[o] - mx, ay = t[o + 1] - my, bx = t[o + 3] - mx, by = t[o + 4] - my, cx = t[o + 6] - mx, cy = t[o + 7] - my;
        if (separates(ux, uy, ax, ay, bx, by, cx, cy, along)) return false;
        if (separates(-uy, ux, ax, ay, bx, by, cx, cy, across)) return false;
        for (int e = 0; e < 3; e++) {
            double ex = e == 0 ? bx - ax : e == 1 ? cx - bx : ax - cx, ey = e == 0 ? by - ay : e == 1 ? cy - by : ay - cy;
            double nx = -ey, ny = ex;
            double half = along * Math.abs(ux * nx + uy * ny) + across * Math.abs(-uy * nx + ux * ny);
            if (separates(nx, ny, ax, ay, bx, by, cx, cy, half)) return false;
        }
        return true;
    }

    /** Whether the axis n separates the three points (relative to the box's centre) from [-half, half]. */
    private static boolean separates(double nx, double ny, double ax, double ay, double bx, double by, double cx, double cy,
                                     double half) {
        double p = nx * ax + ny * ay, q = nx * bx + ny * by, r = nx * cx + ny * cy;
        double slack = 1e-12 * (Math.abs(p) + Math.abs(q) + Math.abs(r) + half);
        return Math.min(p, Math.min(q, r)) > half + slack || Math.max(p, Math.max(q, r)) < -half - slack;
    }

    /** Whether cylinder at offset o comes within reach of the segment from (x0, y0) along (dx, dy), in the plane. */
    private boolean circleNear(int o, double x0, double y0, double dx, double dy, double reach) {
        double px = cylinders[o] - x0, py = cylinders[o + 1] - y0;
        double d2 = dx * dx + dy * dy;
        double f = d2 > 0 ? Math.max(0, Math.min(1, (px * dx + py * dy) / d2)) : 0;
        double ex = px - f * dx, ey = py - f * dy;
        double limit = cylinders[o + 2] + reach;
        return ex * ex + ey * ey <= limit * limit * (1 + 1e-12);
    }
}
