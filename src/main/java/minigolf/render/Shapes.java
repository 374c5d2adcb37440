package minigolf.render;

import java.util.HashMap;
import java.util.Map;
import java.util.function.DoubleBinaryOperator;

/** Small procedural meshes in the position/normal/colour layout ({@link MeshData#PNC}). */
public final class Shapes {
    private Shapes() {
    }

    /** A unit icosphere (radius 1, centred on the origin) subdivided {@code subdivisions} times. */
    public static MeshData icosphere(int subdivisions, float r, float g, float b) {
        double t = (1 + Math.sqrt(5)) / 2;
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        int[] faces = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6,
                7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
        java.util.List<double[]> pts = new java.util.ArrayList<>();
        for (double[] p : base) pts.add(normalize(p));
        for (int s = 0; s < subdivisions; s++) {
            Map<Long, Integer> mid = new HashMap<>();
            int[] next = new int[faces.length * 4];
            int q = 0;
            for (int f = 0; f < faces.length; f += 3) {
                int a = faces[f], bb = faces[f + 1], c = faces[f + 2];
                int ab = midpoint(pts, mid, a, bb), bc = midpoint(pts, mid, bb, c), ca = midpoint(pts, mid, c, a);
                int[] tris = {a, ab, ca, bb, bc, ab, c, ca, bc, ab, bc, ca};
                System.arraycopy(tris, 0, next, q, 12);
                q += 12;
            }
            faces = next;
        }
        float[] v = new float[pts.size() * 9];
        for (int i = 0; i < pts.size(); i++) {
            double[] p = pts.get(i);
            int o = i * 9;
            v[o] = v[o + 3] = (float) p[0];
            v[o + 1] = v[o + 4] = (float) p[1];
            v[o + 2] = v[o + 5] = (float) p[2];
            v[o + 6] = r;
            v[o + 7] = g;
            v[o + 8] = b;
        }
        return new MeshData(MeshData.PNC, v, faces);
    }

    private static int midpoint(java.util.List<double[]> pts, Map<Long, Integer> cache, int a, int b) {
        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
        return cache.computeIfAbsent(key, k -> {
            double[] p = pts.get(a), q = pts.get(b);
            pts.add(normalize(new double[]{p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
            return pts.size() - 1;
        });
    }

    private static double[] normalize(double[] p) {
        double l = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return new double[]{p[0] / l, p[1] / l, p[2] / l};
    }

    /**
     * A disc of {@code radius} around (cx, cy) draped over a surface: each vertex sits at
     * {@code height(x, y) + lift}, so it follows slopes without sinking into them.
     */
    public static MeshData drapedDisc(double cx, double cy, double radius, int segments, int rings,
                                      DoubleBinaryOperator height, double lift, float r, float g, float b) {
        int count = 1 + rings * segments;
        float[] v = new float[count * 9];
        int p = 0;
        p = putPnc(v, p, cx, cy, height.applyAsDouble(cx, cy) + lift, 0, 0, 1, r, g, b);
        for (int ring = 1; ring <= rings; ring++) {
            double rr = radius * ring / rings;
            for (int s = 0; s < segments; s++) {
                double a = 2 * Math.PI * s / segments;
                double x = cx + rr * Math.cos(a), y = cy + rr * Math.sin(a);
                p = putPnc(v, p, x, y, height.applyAsDouble(x, y) + lift, 0, 0, 1, r, g, b);
            }
        }
        int[] idx = new int[3 * segments * (2 * rings - 1)];
        int q = 0;
        for (int s = 0; s < segments; s++) {
            idx[q++] = 0;
            idx[q++] = 1 + s;
            idx[q++] = 1 + (s + 1) % segments;
        }
        for (int ring = 1; ring < rings; ring++) {
            int inner = 1 + (ring - 1) * segments, outer = 1 + ring * segments;
            for (int s = 0; s < segments; s++) {
                int s1 = (s + 1) % segments;
                idx[q++] = inner + s;
                idx[q++] = outer + s;
                idx[q++] = outer + s1;
                idx[q++] = inner + s;
                idx[q++] = outer + s1;
                idx[q++] = inner + s1;
            }
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /** An open cylinder along +z from (x, y, z0) to (x, y, z1), with a flat top cap. */
    public static MeshData cylinder(double x, double y, double z0, double z1, double radius, int segments,
                                    float r, float g, float b) {
        float[] v = new float[(2 * segments + segments + 1) * 9];
        int p = 0;
        for (int s = 0; s < segments; s++) {
            double a = 2 * Math.PI * s / segments, c = Math.cos(a), sn = Math.sin(a);
            p = putPnc(v, p, x + radius * c, y + radius * sn, z0, c, sn, 0, r, g, b);
            p = putPnc(v, p, x + radius * c, y + radius * sn, z1, c, sn, 0, r, g, b);
        }
        int capCentre = 2 * segments;
        p = putPnc(v, p, x, y, z1, 0, 0, 1, r, g, b);
        for (int s = 0; s < segments; s++) {
            double a = 2 * Math.PI * s / segments;
            p = putPnc(v, p, x + radius * Math.cos(a), y + radius * Math.sin(a), z1, 0, 0, 1, r, g, b);
        }
        int[] idx = new int[segments * 9];
        int q = 0;
        for (int s = 0; s < segments; s++) {
            int s1 = (s + 1) % segments;
            int b0 = 2 * s, t0 = 2 * s + 1, b1 = 2 * s1, t1 = 2 * s1 + 1;
            idx[q++] = b0;
            idx[q++] = b1;
            idx[q++] = t1;
            idx[q++] = b0;
            idx[q++] = t1;
            idx[q++] = t0;
            idx[q++] = capCentre;
            idx[q++] = capCentre + 1 + s;
            idx[q++] = capCentre + 1 + s1;
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /**
     * A flat arrow lying on a surface: from {@code start} metres to {@code length} metres along the
     * direction (dirX, dirY) from (x, y), a shaft {@code width} wide and a head twice as wide. Every
     * vertex sits at {@code height(x, y) + lift}; the shaft is cut every 5 cm so it follows the ground.
     */
    public static MeshData groundArrow(double x, double y, double dirX, double dirY, double start, double length,
                                       double width, DoubleBinaryOperator height, double lift,
                                       float r, float g, float b) {
        double len = Math.hypot(dirX, dirY);
        double ux = len > 1e-12 ? dirX / len : 1, uy = len > 1e-12 ? dirY / len : 0;
        double px = -uy, py = ux; // left of the direction
        double head = Math.min(length - start, Math.max(2.5 * width, 0.25 * (length - start)));
        double shaftEnd = length - head;
        int segments = Math.max(1, (int) Math.ceil((shaftEnd - start) / 0.05));
        int headSegments = Math.max(1, (int) Math.ceil(head / 0.05));
        int count = 2 * (segments + 1) + 2 * (headSegments + 1);
        float[] v = new float[count * 9];
        int p = 0;
        for (int s = 0; s <= segments; s++) {
            double d = start + (shaftEnd - start) * s / segments;
            for (int side = -1; side <= 1; side += 2) {
                double vx = x + ux * d + px * side * width / 2, vy = y + uy * d + py * side * width / 2;
                p = putPnc(v, p, vx, vy, height.applyAsDouble(vx, vy) + lift, 0, 0, 1, r, g, b);
            }
        }
        // The head narrows from full width to a point: pairs of vertices converging on the tip.
        for (int s = 0; s <= headSegments; s++) {
            double t = (double) s / headSegments, d = shaftEnd + head * t, half = width * (1 - t);
            for (int side = -1; side <= 1; side += 2) {
                double vx = x + ux * d + px * side * half, vy = y + uy * d + py * side * half;
                p = putPnc(v, p, vx, vy, height.applyAsDouble(vx, vy) + lift, 0, 0, 1, r, g, b);
            }
        }
        int[] idx = new int[6 * (segments + headSegments)];
        int q = 0;
        for (int s = 0; s < segments + 1 + headSegments; s++) {
            if (s == segments) continue; // no quad between the shaft's end and the head's base
            int a = 2 * s, c = a + 2;
            idx[q++] = a;
            idx[q++] = c;
            idx[q++] = c + 1;
            idx[q++] = a;
            idx[q++] = c + 1;
            idx[q++] = a + 1;
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /** The height a dot is drawn at, from the path's (x, y, z). */
    @FunctionalInterface
    public interface DotHeight {
        double at(double x, double y, double z);
    }

    /**
     * Flat round dots (8-sided, facing up) along a polyline of (x, y, z) triplets: the first
     * {@code skip} metres left out, then one every {@code spacing} metres of the path's length in
     * the plane, each at {@code height.at(x, y, z)}. Null if the path is too short for a dot.
     */
    public static MeshData dotsAlong(float[] path, double spacing, double skip, double radius, DotHeight height,
                                     float r, float g, float b) {
        java.util.List<double[]> centres = new java.util.ArrayList<>();
        double next = skip, walked = 0;
        for (int i = 3; i + 2 < path.length; i += 3) {
            double x0 = path[i - 3], y0 = path[i - 2], z0 = path[i - 1], x1 = path[i], y1 = path[i + 1], z1 = path[i + 2];
            double seg = Math.hypot(x1 - x0, y1 - y0);
            while (seg > 0 && next <= walked + seg) {
                double t = (next - walked) / seg;
                centres.add(new double[]{x0 + t * (x1 - x0), y0 + t * (y1 - y0), z0 + t * (z1 - z0)});
                next += spacing;
            }
            walked += seg;
        }
        if (centres.isEmpty()) return null;
        int sides = 8;
        float[] v = new float[centres.size() * (sides + 1) * 9];
        int[] idx = new int[centres.size() * sides * 3];
        int p = 0, q = 0;
        for (int d = 0; d < centres.size(); d++) {
            double[] c = centres.get(d);
            double z = height.at(c[0], c[1], c[2]);
            int centre = d * (sides + 1);
            p = putPnc(v, p, c[0], c[1], z, 0, 0, 1, r, g, b);
            for (int s = 0; s < sides; s++) {
                double a = 2 * Math.PI * s / sides;
                p = putPnc(v, p, c[0] + radius * Math.cos(a), c[1] + radius * Math.sin(a), z, 0, 0, 1, r, g, b);
                idx[q++] = centre;
                idx[q++] = centre + 1 + s;
                idx[q++] = centre + 1 + (s + 1) % sides;
            }
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /**
     * A flat ring between {@code inner} and {@code outer} round (cx, cy), draped over a surface at
     * {@code height(x, y) + lift} (the current player's ball marker).
     */
    public static MeshData drapedRing(double cx, double cy, double inner, double outer, int segments,
                                      DoubleBinaryOperator height, double lift, float r, float g, float b) {
        float[] v = new float[2 * segments * 9];
        int p = 0;
        for (int s = 0; s < segments; s++) {
            double a = 2 * Math.PI * s / segments, c = Math.cos(a), sn = Math.sin(a);
            for (double rr : new double[]{inner, outer}) {
                double x = cx + rr * c, y = cy + rr * sn;
                p = putPnc(v, p, x, y, height.applyAsDouble(x, y) + lift, 0, 0, 1, r, g, b);
            }
        }
        int[] idx = new int[6 * segments];
        int q = 0;
        for (int s = 0; s < segments; s++) {
            int i0 = 2 * s, o0 = i0 + 1, i1 = 2 * ((s + 1) % segments), o1 = i1 + 1;
            idx[q++] = i0;
            idx[q++] = o0;
            idx[q++] = o1;
            idx[q++] = i0;
            idx[q++] = o1;
            idx[q++] = i1;
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /**
     * Flat round dots at the points of a path ((x, y, z) triplets, oldest first), each at
     * {@code height.at(x, y, z)}, growing from a fifth of {@code radius} at the old end to
     * {@code radius} at the new: a trail that fades out behind the ball. Null for fewer than two points.
     */
    public static MeshData trail(float[] path, double radius, DotHeight height, float r, float g, float b) {
        int n = path.length / 3;
        if (n < 2) return null;
        int sides = 8;
        float[] v = new float[n * (sides + 1) * 9];
        int[] idx = new int[n * sides * 3];
        int p = 0, q = 0;
        for (int d = 0; d < n; d++) {
            double x = path[3 * d], y = path[3 * d + 1], z = height.at(x, y, path[3 * d + 2]);
            double rad = radius * (0.2 + 0.8 * d / (n - 1));
            int centre = d * (sides + 1);
            p = putPnc(v, p, x, y, z, 0, 0, 1, r, g, b);
            for (int s = 0; s < sides; s++) {
                double a = 2 * Math.PI * s / sides;
                p = putPnc(v, p, x + rad * Math.cos(a), y + rad * Math.sin(a), z, 0, 0, 1, r, g, b);
                idx[q++] = centre;
                idx[q++] = centre + 1 + s;
                idx[q++] = centre + 1 + (s + 1) % sides;
            }
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    static int putPnc(float[] v, int p, double x, double y, double z, double nx, double ny, double nz,
                      float r, float g, float b) {
        v[p++] = (float) x;
        v[p++] = (float) y;
        v[p++] = (float) z;
        v[p++] = (float) nx;
        v[p++] = (float) ny;
        v[p++] = (float) nz;
        v[p++] = r;
        v[p++] = g;
        v[p++] = b;
        return p;
    }
}
