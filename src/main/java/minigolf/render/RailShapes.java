package minigolf.render;

import minigolf.collision.ObstacleGeometry;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;

/**
 * A wall drawn as a rail with a rounded top, inside the very slab the physics collides with
 * ({@link ObstacleGeometry}: the same ends, thickness, sloping top line and footing): its upper edges
 * are rounded with radius {@code min(thickness/2, 3 cm)} (a half-round cap on a usual 8 cm rail), with
 * smooth normals, so light runs over it as over a planed board or dressed coping. Also darker towards
 * its foot (a baked contact shade: 75% at the ground, 55% at the footing), at every quality. Plain
 * Java: triangles with per-vertex normals and shade factors, for {@link ObstacleMeshes}.
 */
public final class RailShapes {
    /** The largest rounding radius (metres). */
    static final double MAX_ROUNDING = 0.03;
    /** Segments per quarter circle of the rounding. */
    static final int QUARTER_SEGMENTS = 4;
    static final float GROUND_SHADE = 0.75f, FOOTING_SHADE = 0.55f;
    private static final int GROUND_SAMPLES = 32;

    private RailShapes() {
    }

    /** Receives triangles' corners: position, normal, and a shade factor for the colour. */
    interface Sink {
        void vertex(double x, double y, double z, double nx, double ny, double nz, float shade);
    }

    /** Writes the rounded wall as triangles (3 calls per triangle); a wall of no thickness is not rounded (returns false). */
    static boolean roundedWall(Obstacle.Wall w, HeightProbe ground, Sink out) {
        double half = w.thickness() / 2;
        if (half <= 0) return false;
        double ax = w.from().x(), ay = w.from().y(), bx = w.to().x(), by = w.to().y();
        double dx = bx - ax, dy = by - ay, length = Math.hypot(dx, dy);
        double ux = length > 0 ? dx / length : 1, uy = length > 0 ? dy / length : 0;
        double topA = ground.height(ax, ay) + w.height(), topB = ground.height(bx, by) + w.height();
        double lowest = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= GROUND_SAMPLES; k++) {
            double s = (double) k / GROUND_SAMPLES;
            lowest = Math.min(lowest, ground.height(ax + s * dx, ay + s * dy));
        }
        double bottom = lowest - ObstacleGeometry.FOOTING;
        double r = Math.min(half, Math.min(MAX_ROUNDING, w.height()));
        double px = -uy, py = ux; // across the rail, unit
        double[][] ends = {{ax - half * ux, ay - half * uy, topA}, {bx + half * ux, by + half * uy, topB}};
        // The profile across the rail, from the +p side's foot round the top to the -p side's foot:
        // offset across, height below the top (<= 0), and the normal's (across, up) components.
        int n = 2 * QUARTER_SEGMENTS + 2;
        double[][] profile = new double[n + 2][];
        profile[0] = new double[]{half, Double.NaN, 1, 0}; // the foot: z set per end (bottom)
        for (int k = 0; k <= QUARTER_SEGMENTS; k++) {
            double a = 0.5 * Math.PI * k / QUARTER_SEGMENTS;
            profile[1 + k] = new double[]{half - r + r * Math.cos(a), -r + r * Math.sin(a), Math.cos(a), Math.sin(a)};
        }
        for (int k = 0; k <= QUARTER_SEGMENTS; k++) {
            double a = 0.5 * Math.PI + 0.5 * Math.PI * k / QUARTER_SEGMENTS;
            profile[2 + QUARTER_SEGMENTS + k] = new double[]{-(half - r) + r * Math.cos(a), -r + r * Math.sin(a), Math.cos(a), Math.sin(a)};
        }
        profile[n + 1] = new double[]{-half, Double.NaN, -1, 0};
        // Sides: footing to ground level to the start of the rounding, both faces.
        for (int side = -1; side <= 1; side += 2) {
            double ox = side * half * px, oy = side * half * py;
            double[] zs = {bottom, lowest, Double.NaN};
            float[] shades = {FOOTING_SHADE, GROUND_SHADE, 1f};
            for (int band = 0; band < 2; band++) {
                double[][] q = new double[4][];
                for (int e = 0; e < 2; e++) {
                    double top = ends[e][2] - r;
                    double z0 = zs[band], z1 = band == 1 ? top : Math.min(zs[band + 1], top);
                    q[e == 0 ? 0 : 1] = new double[]{ends[e][0] + ox, ends[e][1] + oy, Math.min(z0, top), shades[band]};
                    q[e == 0 ? 3 : 2] = new double[]{ends[e][0] + ox, ends[e][1] + oy, z1, shades[band + 1]};
                }
                quad(out, q, side * px, side * py, 0);
            }
        }
        // The rounded cap: quads between consecutive profile points along the rail, smooth normals.
        for (int k = 1; k < n; k++) {
            double[] a = profile[k], b = profile[k + 1];
            double[][] c = new double[4][];
            c[0] = capPoint(ends[0], px, py, a);
            c[1] = capPoint(ends[1], px, py, a);
            c[2] = capPoint(ends[1], px, py, b);
            c[3] = capPoint(ends[0], px, py, b);
            emit(out, c[0], a, px, py);
            emit(out, c[1], a, px, py);
            emit(out, c[2], b, px, py);
            emit(out, c[0], a, px, py);
            emit(out, c[2], b, px, py);
            emit(out, c[3], b, px, py);
        }
        // The end faces: the profile closed by the footing, a convex polygon, as a fan.
        for (int e = 0; e < 2; e++) {
            double nx = e == 0 ? -ux : ux, ny = e == 0 ? -uy : uy;
            double[][] ring = new double[n + 2][];
            for (int k = 0; k < ring.length; k++) {
                double[] pr = profile[k];
                double z = Double.isNaN(pr[1]) ? bottom : ends[e][2] + pr[1];
                ring[k] = new double[]{ends[e][0] + pr[0] * px, ends[e][1] + pr[0] * py, z};
            }
            for (int k = 1; k + 1 < ring.length; k++) {
                int i1 = e == 0 ? k + 1 : k, i2 = e == 0 ? k : k + 1; // outward winding
                fanVertex(out, ring[0], nx, ny, bottom, lowest);
                fanVertex(out, ring[i1], nx, ny, bottom, lowest);
                fanVertex(out, ring[i2], nx, ny, bottom, lowest);
            }
        }
        return true;
    }

    private static double[] capPoint(double[] end, double px, double py, double[] pr) {
        return new double[]{end[0] + pr[0] * px, end[1] + pr[0] * py, end[2] + pr[1]};
    }

    private static void emit(Sink out, double[] p, double[] pr, double px, double py) {
        out.vertex(p[0], p[1], p[2], pr[2] * px, pr[2] * py, pr[3], 1f);
    }

    private static void fanVertex(Sink out, double[] p, double nx, double ny, double bottom, double ground) {
        float shade = p[2] <= bottom + 1e-9 ? FOOTING_SHADE : (p[2] <= ground ? GROUND_SHADE : 1f);
        out.vertex(p[0], p[1], p[2], nx, ny, 0, shade);
    }

    /** Two triangles of a quad {x, y, z, shade} x 4 (corners in order) with one normal. */
    private static void quad(Sink out, double[][] q, double nx, double ny, double nz) {
        int[] order = {0, 1, 2, 0, 2, 3};
        for (int i : order) out.vertex(q[i][0], q[i][1], q[i][2], nx, ny, nz, (float) q[i][3]);
    }
}
