package minigolf.collision;

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
