package minigolf.collision;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;

/**
 * The course's still obstacles as static collision geometry for a ball of one radius: triangles
 * (walls, boxes, models) and vertical cylinders (trees, bumpers), in a uniform grid over the course
 * plane. Gates and moving obstacles are left out (they have their own collision code).
 *
 * <p>Broad phase ({@link ShapeGrid}): each shape is listed in every grid cell its bounding box
 * touches; a sweep visits only the cells its own bounding box touches and skips shapes whose 3-D
 * bounding box it misses, so 500 obstacles cost about what 5 do unless the ball is among them.
 * Before sweeping a path the physics may ask whether anything is near it at all
 * ({@link PathProximity}). Narrow phase: the exact time of impact of the swept sphere with faces,
 * edges and vertices ({@link SweepTests}), cylinder sides and tops. Immutable: one scene serves
 * every thread.
 */
public final class CollisionScene {
    /** Triangles per obstacle tree-top rim: the rim circle is a 32-gon (within 0.5% of the radius). */
    private static final int RIM_SEGMENTS = 32;

    private final double radius;
    // Triangles: 9 vertex coordinates + unit normal (12 doubles); bounding boxes 6 doubles per shape.
    private final double[] triangles;
    private final double[] cylinders; // cx, cy, R, zBottom, zTop
    private final double[] boxes;     // per shape: minX, minY, minZ, maxX, maxY, maxZ (triangles first, then cylinders)
    private final double[] restitution;
    private final int[] obstacleOf;
    private final int triangleCount;
    /** The broad phase: which shapes are listed where. */
    private final ShapeGrid grid;
    private final PathProximity proximity;

    private CollisionScene(double radius, double[] triangles, double[] cylinders, double[] restitution, int[] obstacleOf,
                           Bounds bounds) {
        this.radius = radius;
        this.triangles = triangles;
        this.cylinders = cylinders;
        this.triangleCount = triangles.length / 12;
        this.restitution = restitution;
        this.obstacleOf = obstacleOf;
        int shapes = triangleCount + cylinders.length / 5;
        boxes = new double[6 * shapes];
        for (int s = 0; s < shapes; s++) shapeBox(s, boxes, 6 * s);
        grid = new ShapeGrid(boxes, obstacleOf, radius, bounds);
        proximity = new PathProximity(grid, radius, triangles, cylinders, boxes);
    }

    /**
     * Builds the scene of a course's obstacles for a ball of radius {@code ballRadius}.
     *
     * @param ground the terrain height, which walls and trees stand on
     */
    public static CollisionScene build(List<Obstacle> obstacles, HeightProbe ground, Bounds bounds, double ballRadius) {
        List<double[]> tris = new ArrayList<>();
        List<double[]> cyls = new ArrayList<>();
        List<Double> triRest = new ArrayList<>(), cylRest = new ArrayList<>();
        List<Integer> triOwner = new ArrayList<>(), cylOwner = new ArrayList<>();
        for (int k = 0; k < obstacles.size(); k++) {
            Obstacle o = obstacles.get(k);
            // Gates and moving obstacles have their own collision code (minigolf.collision.Gates, MovingObstacles).
            if (!ObstacleGeometry.isStillSolid(o)) continue;
            if (ObstacleGeometry.isCylinder(o)) {
                cyls.add(ObstacleGeometry.cylinder(o, ground));
                cylRest.add(o.restitution());
                cylOwner.add(k);
                continue;
            }
            double[] t = ObstacleGeometry.triangles(o, ground);
            for (int i = 0; i + 9 <= t.length; i += 9) {
                double[] tri = withNormal(t, i);
                if (tri == null) continue; // a degenerate triangle has no area to hit
                tris.add(tri);
                triRest.add(o.restitution());
                triOwner.add(k);
            }
        }
        double[] triangles = new double[12 * tris.size()];
        for (int i = 0; i < tris.size(); i++) System.arraycopy(tris.get(i), 0, triangles, 12 * i, 12);
        double[] cylinders = new double[5 * cyls.size()];
        for (int i = 0; i < cyls.size(); i++) System.arraycopy(cyls.get(i), 0, cylinders, 5 * i, 5);
        int shapes = tris.size() + cyls.size();
        double[] rest = new double[shapes];
        int[] owner = new int[shapes];
        for (int i = 0; i < tris.size(); i++) {
            rest[i] = triRest.get(i);
            owner[i] = triOwner.get(i);
        }
        for (int i = 0; i < cyls.size(); i++) {
            rest[tris.size() + i] = cylRest.get(i);
            owner[tris.size() + i] = cylOwner.get(i);
        }
        return new CollisionScene(ballRadius, triangles, cylinders, rest, owner, bounds);
    }

    private static double[] withNormal(double[] t, int i) {
        double ux = t[i + 3] - t[i], uy = t[i + 4] - t[i + 1], uz = t[i + 5] - t[i + 2];
        double wx = t[i + 6] - t[i], wy = t[i + 7] - t[i + 1], wz = t[i + 8] - t[i + 2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 1e-14)) return null;
        double[] out = Arrays.copyOfRange(t, i, i + 12);
        out[9] = nx / length;
        out[10] = ny / length;
        out[11] = nz / length;
        return out;
    }

    public boolean isEmpty() {
        return boxes.length == 0;
    }

    public double ballRadius() {
        return radius;
    }

    /** The box round every shape, {minX, minY, minZ, maxX, maxY, maxZ} (all infinities when empty). */
    public double[] extent() {
        double[] e = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int b = 0; b < boxes.length; b += 6) {
            for (int k = 0; k < 3; k++) {
                e[k] = Math.min(e[k], boxes[b + k]);
                e[k + 3] = Math.max(e[k + 3], boxes[b + k + 3]);
            }
        }
        return e;
    }

    public int triangleCount() {
        return triangleCount;
    }

    public int cylinderCount() {
        return cylinders.length / 5;
    }

    /** Whether any shape is listed in the grid cells under the rectangle (a cheap test before a sweep). */
    public boolean anyNear(double minX, double minY, double maxX, double maxY) {
        return grid.anyListed(minX, minY, maxX, maxY);
    }

    /**
     * Whether a shape's bounding box comes within a ball radius of the rectangle in the plane: a
     * sweep of the centre along any path inside the rectangle can only touch such a shape (a
     * sweep skips shapes whose box is further from its own chord). Cheaper than the sweeps of a
     * curved path's chords, and exact as a "no": it never hides a contact.
     */
    public boolean anyShapeNear(double minX, double minY, double maxX, double maxY) {
        return proximity.anyShapeNear(minX, minY, maxX, maxY);
    }

    /**
     * Whether a shape may come within {@code margin} of the segment from (x0, y0) to (x1, y1) in
     * the plane, a ball radius added: a sweep of the centre along any path that stays within
     * {@code margin} of the segment can only touch such a shape. Tighter than
     * {@link #anyShapeNear} round the segment's rectangle (a diagonal path's rectangle is mostly
     * empty of it): the shapes near are tested by their outlines in the plane (a run of one
     * obstacle's triangles by the convex hull of their outlines, separating axes against the box
     * round the segment; a cylinder's circle by its distance). Exact as a "no", with a nanometre
     * to spare for rounding.
     */
    public boolean anyShapeNearPath(double x0, double y0, double x1, double y1, double margin) {
        return proximity.anyShapeNearPath(x0, y0, x1, y1, margin);
    }

    /** For tests: the path proximity's hull points, stored and listed by the runs. */
    long[] hullPoints() {
        return proximity.hullPoints();
    }

    /**
     * How many shape entries a sweep from (x0, y0) to (x1, y1) visits: those listed in the grid cells
     * under its rectangle (a shape listed in two of them counts twice), before their boxes are tested.
     * For tests: the broad phase keeps this small whatever the number of shapes.
     */
    int candidates(double x0, double y0, double x1, double y1) {
        return grid.entries(Math.min(x0, x1), Math.min(y0, y1), Math.max(x0, x1), Math.max(y0, y1));
    }

    /**
     * Sweeps the ball's centre from p0 to p1 and reports the first contact, if any, in {@code hit}.
     * {@code scratch} must hold at least 3 doubles (one per thread).
     */
    public boolean sweep(double x0, double y0, double z0, double x1, double y1, double z1, Hit hit, double[] scratch) {
        return sweep(x0, y0, z0, x1, y1, z1, hit, scratch, null);
    }

    /**
     * As {@link #sweep(double, double, double, double, double, double, Hit, double[])}, passing over
     * the obstacles whose entry in {@code gone} is true (bricks broken earlier; null: none).
     */
    public boolean sweep(double x0, double y0, double z0, double x1, double y1, double z1, Hit hit, double[] scratch,
                         boolean[] gone) {
        double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
        double r = radius;
        double minX = Math.min(x0, x1) - r, maxX = Math.max(x0, x1) + r;
        double minY = Math.min(y0, y1) - r, maxY = Math.max(y0, y1) + r;
        double minZ = Math.min(z0, z1) - r, maxZ = Math.max(z0, z1) + r;
        ShapeGrid g = grid;
        int i0 = g.column(minX + r), i1 = g.column(maxX - r), j0 = g.row(minY + r), j1 = g.row(maxY - r);
        double best = Double.POSITIVE_INFINITY;
        int columns = g.columns;
        int[] cellRuns = g.cellRuns, runStart = g.runStart, cellItems = g.cellItems, firstColumn = g.firstColumn,
                firstRow = g.firstRow;
        float[] runBox = g.runBoxes;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                int c = j * columns + i;
                for (int q = cellRuns[c], last = cellRuns[c + 1]; q < last; q++) {
                    int rb = 6 * q;
                    if (runBox[rb] > maxX || runBox[rb + 3] < minX || runBox[rb + 1] > maxY || runBox[rb + 4] < minY
                            || runBox[rb + 2] > maxZ || runBox[rb + 5] < minZ) {
                        continue;
                    }
                    for (int k = runStart[q], end = runStart[q + 1]; k < end; k++) {
                        int s = cellItems[k];
                        int b = 6 * s;
                        if (boxes[b] > maxX || boxes[b + 3] < minX || boxes[b + 1] > maxY || boxes[b + 4] < minY
                                || boxes[b + 2] > maxZ || boxes[b + 5] < minZ) {
                            continue;
                        }
                        // A shape listed in several cells is tested in the first of them this sweep visits.
                        if ((i > i0 && firstColumn[s] < i) || (j > j0 && firstRow[s] < j)) continue;
                        if (gone != null && gone[obstacleOf[s]]) continue;
                        double t = s < triangleCount
                                ? triangle(s, x0, y0, z0, dx, dy, dz, best, scratch)
                                : cylinder(s - triangleCount, x0, y0, z0, dx, dy, dz, best, scratch);
                        if (t < best) {
                            best = t;
                            hit.still(t, scratch[0], scratch[1], scratch[2], restitution[s], obstacleOf[s]);
                        }
                    }
                }
            }
        }
        return best <= 1;
    }

    /** Face, then edges and corners of triangle s: the first contact before {@code limit}. */
    private double triangle(int s, double px, double py, double pz, double dx, double dy, double dz, double limit,
                            double[] out) {
        double[] tr = triangles;
        int o = 12 * s;
        double r = radius;
        double nx = tr[o + 9], ny = tr[o + 10], nz = tr[o + 11];
        double s0 = nx * (px - tr[o]) + ny * (py - tr[o + 1]) + nz * (pz - tr[o + 2]);
        double rate = nx * dx + ny * dy + nz * dz;
        double s1 = s0 + rate;
        // Two-sided: the side the centre starts on faces it.
        double sign = s0 >= 0 ? 1 : -1;
        double a = sign * s0, b = sign * s1;
        if (a >= r && b >= r) return Double.POSITIVE_INFINITY; // never within reach of the plane
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double best = limit;
        if (b < a - SweepTests.ALONG * length) {
            double t = a <= r ? 0 : (a - r) / (a - b);
            if (t < best) {
                double cx = px + t * dx, cy = py + t * dy, cz = pz + t * dz;
                double d = nx * (cx - tr[o]) + ny * (cy - tr[o + 1]) + nz * (cz - tr[o + 2]);
                if (inside(o, cx - d * nx, cy - d * ny, cz - d * nz)) {
                    out[0] = sign * nx;
                    out[1] = sign * ny;
                    out[2] = sign * nz;
                    return t; // a face contact comes before any contact with the face's own edges
                }
            }
        }
        // Each test is limited to the best contact so far and writes out only for a nearer one, so
        // out always holds the normal of the best.
        boolean found = false;
        for (int e = 0; e < 3; e++) {
            int a0 = o + 3 * e, a1 = o + 3 * ((e + 1) % 3);
            double t = SweepTests.segment(px, py, pz, dx, dy, dz, r, tr[a0], tr[a0 + 1], tr[a0 + 2],
                    tr[a1], tr[a1 + 1], tr[a1 + 2], best, out);
            if (t < best) {
                best = t;
                found = true;
            }
            t = SweepTests.point(px, py, pz, dx, dy, dz, r, tr[a0], tr[a0 + 1], tr[a0 + 2], best, out);
            if (t < best) {
                best = t;
                found = true;
            }
        }
        return found ? best : Double.POSITIVE_INFINITY;
    }

    /** Whether the point q in the triangle's plane lies inside the triangle (edges included). */
    private boolean inside(int o, double qx, double qy, double qz) {
        double[] tr = triangles;
        double nx = tr[o + 9], ny = tr[o + 10], nz = tr[o + 11];
        for (int e = 0; e < 3; e++) {
            int a = o + 3 * e, b = o + 3 * ((e + 1) % 3);
            double ex = tr[b] - tr[a], ey = tr[b + 1] - tr[a + 1], ez = tr[b + 2] - tr[a + 2];
            double wx = qx - tr[a], wy = qy - tr[a + 1], wz = qz - tr[a + 2];
            double cx = ey * wz - ez * wy, cy = ez * wx - ex * wz, cz = ex * wy - ey * wx;
            if (cx * nx + cy * ny + cz * nz < 0) return false;
        }
        return true;
    }

    /** The side, the flat top and the top rim (a 32-gon of edges) of cylinder c. */
    private double cylinder(int c, double px, double py, double pz, double dx, double dy, double dz, double limit,
                            double[] out) {
        int o = 5 * c;
        double cx = cylinders[o], cy = cylinders[o + 1], big = cylinders[o + 2], bottom = cylinders[o + 3], top = cylinders[o + 4];
        double r = radius;
        double best = limit;
        boolean found = false; // as in triangle(): out holds the best contact's normal
        // Side: the centre's horizontal distance from the axis falls to R + r while beside the trunk.
        double mx = px - cx, my = py - cy;
        double a = dx * dx + dy * dy, b = mx * dx + my * dy, k = mx * mx + my * my - (big + r) * (big + r);
        if (b < 0) {
            double t;
            if (k <= 0) {
                t = 0;
            } else {
                double disc = b * b - a * k;
                t = disc >= 0 && a > 0 ? k / (-b + Math.sqrt(disc)) : Double.POSITIVE_INFINITY;
            }
            double z = pz + t * dz;
            if (t <= 1 && t < best && z >= bottom && z <= top) {
                double hx = mx + t * dx, hy = my + t * dy, h = Math.hypot(hx, hy);
                if (h > 0) {
                    best = t;
                    out[0] = hx / h;
                    out[1] = hy / h;
                    out[2] = 0;
                    found = true;
                }
            }
        }
        // Top: the centre comes down to r above the top while over the disc.
        double above0 = pz - top, above1 = above0 + dz;
        if (dz < 0 && above0 >= r - 1e-12 && above1 < r) {
            double t = Math.max(0, (above0 - r) / (above0 - above1));
            double hx = mx + t * dx, hy = my + t * dy;
            if (t < best && hx * hx + hy * hy <= big * big) {
                best = t;
                out[0] = 0;
                out[1] = 0;
                out[2] = 1;
                found = true;
            }
        }
        // Rim: only where the centre passes within r of the top's height.
        if (Math.min(pz, pz + dz) <= top + r && Math.max(pz, pz + dz) >= top - r) {
            for (int s = 0; s < RIM_SEGMENTS; s++) {
                double a0 = 2 * Math.PI * s / RIM_SEGMENTS, a1 = 2 * Math.PI * (s + 1) / RIM_SEGMENTS;
                double ax = cx + big * Math.cos(a0), ay = cy + big * Math.sin(a0);
                double ex = cx + big * Math.cos(a1), ey = cy + big * Math.sin(a1);
                double t = SweepTests.segment(px, py, pz, dx, dy, dz, r, ax, ay, top, ex, ey, top, best, out);
                if (t < best) {
                    best = t;
                    found = true;
                }
                t = SweepTests.point(px, py, pz, dx, dy, dz, r, ax, ay, top, best, out);
                if (t < best) {
                    best = t;
                    found = true;
                }
            }
        }
        return found ? best : Double.POSITIVE_INFINITY;
    }

    /**
     * The distance from the point to the nearest obstacle surface or inside (0 inside a tree); for
     * checks that a ball's centre keeps at least the ball's radius from every obstacle.
     * Brute force over every shape.
     */
    public double clearance(double x, double y, double z) {
        double best = Double.POSITIVE_INFINITY;
        for (int s = 0; s < triangleCount; s++) best = Math.min(best, Math.sqrt(triangleDistanceSquared(12 * s, x, y, z)));
        for (int c = 0; c < cylinders.length / 5; c++) {
            int o = 5 * c;
            double radial = Math.max(0, Math.hypot(x - cylinders[o], y - cylinders[o + 1]) - cylinders[o + 2]);
            double vertical = z > cylinders[o + 4] ? z - cylinders[o + 4] : z < cylinders[o + 3] ? cylinders[o + 3] - z : 0;
            best = Math.min(best, Math.hypot(radial, vertical));
        }
        return best;
    }

    /** Squared distance from p to the triangle at offset o (Ericson, Real-Time Collision Detection 5.1.5). */
    private double triangleDistanceSquared(int o, double px, double py, double pz) {
        double[] t = triangles;
        double ax = t[o], ay = t[o + 1], az = t[o + 2];
        double abx = t[o + 3] - ax, aby = t[o + 4] - ay, abz = t[o + 5] - az;
        double acx = t[o + 6] - ax, acy = t[o + 7] - ay, acz = t[o + 8] - az;
        double apx = px - ax, apy = py - ay, apz = pz - az;
        double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
        double qx, qy, qz;
        if (d1 <= 0 && d2 <= 0) return sq(apx, apy, apz);
        double bpx = px - t[o + 3], bpy = py - t[o + 4], bpz = pz - t[o + 5];
        double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
        if (d3 >= 0 && d4 <= d3) return sq(bpx, bpy, bpz);
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double v = d1 / (d1 - d3);
            return sq(apx - v * abx, apy - v * aby, apz - v * abz);
        }
        double cpx = px - t[o + 6], cpy = py - t[o + 7], cpz = pz - t[o + 8];
        double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
        if (d6 >= 0 && d5 <= d6) return sq(cpx, cpy, cpz);
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double w = d2 / (d2 - d6);
            return sq(apx - w * acx, apy - w * acy, apz - w * acz);
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
            double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            qx = t[o + 3] + w * (t[o + 6] - t[o + 3]);
            qy = t[o + 4] + w * (t[o + 7] - t[o + 4]);
            qz = t[o + 5] + w * (t[o + 8] - t[o + 5]);
            return sq(px - qx, py - qy, pz - qz);
        }
        double denom = 1 / (va + vb + vc);
        double v = vb * denom, w = vc * denom;
        qx = ax + abx * v + acx * w;
        qy = ay + aby * v + acy * w;
        qz = az + abz * v + acz * w;
        return sq(px - qx, py - qy, pz - qz);
    }

    private static double sq(double x, double y, double z) {
        return x * x + y * y + z * z;
    }

    private void shapeBox(int s, double[] out, int at) {
        if (s < triangleCount) {
            int o = 12 * s;
            for (int a = 0; a < 3; a++) {
                out[at + a] = Math.min(triangles[o + a], Math.min(triangles[o + 3 + a], triangles[o + 6 + a]));
                out[at + 3 + a] = Math.max(triangles[o + a], Math.max(triangles[o + 3 + a], triangles[o + 6 + a]));
            }
        } else {
            int o = 5 * (s - triangleCount);
            double r = cylinders[o + 2];
            out[at] = cylinders[o] - r;
            out[at + 1] = cylinders[o + 1] - r;
            out[at + 2] = cylinders[o + 3];
            out[at + 3] = cylinders[o] + r;
            out[at + 4] = cylinders[o + 1] + r;
            out[at + 5] = cylinders[o + 4];
        }
    }
}
