package minigolf.scenery;

import java.util.Arrays;

/**
 * Builds the props' triangle meshes on the CPU: interleaved position, normal, colour (9 floats a
 * vertex) and indices, from a few primitives (boxes, frustums, lumps, quads), flat-shaded where a
 * shape has edges. Plain Java; the renderer uploads {@link #vertices()} and {@link #indices()}.
 */
public final class MeshWriter {
    public static final int STRIDE = 9;
    private float[] v = new float[STRIDE * 256];
    private int[] idx = new int[384];
    private int floats, count;

    public int vertexCount() {
        return floats / STRIDE;
    }

    public int indexCount() {
        return count;
    }

    public float[] vertices() {
        return Arrays.copyOf(v, floats);
    }

    public int[] indices() {
        return Arrays.copyOf(idx, count);
    }

    /** Adds a vertex and returns its index. */
    public int vertex(double x, double y, double z, double nx, double ny, double nz, float[] c) {
        if (floats + STRIDE > v.length) v = Arrays.copyOf(v, 2 * v.length);
        double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (l == 0) l = 1;
        v[floats++] = (float) x;
        v[floats++] = (float) y;
        v[floats++] = (float) z;
        v[floats++] = (float) (nx / l);
        v[floats++] = (float) (ny / l);
        v[floats++] = (float) (nz / l);
        v[floats++] = c[0];
        v[floats++] = c[1];
        v[floats++] = c[2];
        return floats / STRIDE - 1;
    }

    /** The box round the vertices from {@code firstVertex} on: min x, y, z, max x, y, z. */
    public float[] box(int firstVertex) {
        float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int i = firstVertex * STRIDE; i < floats; i += STRIDE) {
            for (int a = 0; a < 3; a++) {
                box[a] = Math.min(box[a], v[i + a]);
                box[a + 3] = Math.max(box[a + 3], v[i + a]);
            }
        }
        return box;
    }

    public void triangle(int a, int b, int c) {
        if (count + 3 > idx.length) idx = Arrays.copyOf(idx, 2 * idx.length);
        idx[count++] = a;
        idx[count++] = b;
        idx[count++] = c;
    }

    /** A flat-shaded triangle of its own three vertices. */
    public void flatTriangle(double[] a, double[] b, double[] c, float[] colour) {
        double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
        double wx = c[0] - a[0], wy = c[1] - a[1], wz = c[2] - a[2];
        double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
        if (nx * nx + ny * ny + nz * nz == 0) return;
        int i = vertex(a[0], a[1], a[2], nx, ny, nz, colour);
        int j = vertex(b[0], b[1], b[2], nx, ny, nz, colour);
        int k = vertex(c[0], c[1], c[2], nx, ny, nz, colour);
        triangle(i, j, k);
    }

    /** A flat quad a-b-c-d (counter-clockwise seen from outside). */
    public void flatQuad(double[] a, double[] b, double[] c, double[] d, float[] colour) {
        flatTriangle(a, b, c, colour);
        flatTriangle(a, c, d, colour);
    }

    /**
     * A box centred at (x, y) standing on z0 up to z1, sx by sy, turned by {@code turnDeg} about the
     * vertical; the top may be shrunk by {@code taper} (1 straight, 0.8 a little pyramid-like).
     */
    public void box(double x, double y, double z0, double z1, double sx, double sy, double turnDeg, double taper, float[] colour) {
        double a = Math.toRadians(turnDeg), cos = Math.cos(a), sin = Math.sin(a);
        double[][] c = new double[8][];
        double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; k++) {
            for (int level = 0; level < 2; level++) {
                double s = level == 0 ? 1 : taper;
                double px = corners[k][0] * sx / 2 * s, py = corners[k][1] * sy / 2 * s;
                c[k + 4 * level] = new double[]{x + cos * px - sin * py, y + sin * px + cos * py, level == 0 ? z0 : z1};
            }
        }
        for (int k = 0; k < 4; k++) flatQuad(c[k], c[(k + 1) % 4], c[4 + (k + 1) % 4], c[4 + k], colour);
        flatQuad(c[4], c[5], c[6], c[7], colour);
    }

    /**
     * A frustum round the vertical axis at (x, y): radius r0 at z0 to r1 at z1, {@code sides} sides;
     * {@code smooth} gives round shading (a trunk, a tower), else facets. r1 = 0 makes a cone. The top
     * is closed when r1 > 0.
     */
    public void frustum(double x, double y, double z0, double z1, double r0, double r1, int sides, boolean smooth, float[] colour) {
        double slope = (r0 - r1) / Math.max(1e-9, z1 - z0);
        for (int k = 0; k < sides; k++) {
            double a0 = 2 * Math.PI * k / sides, a1 = 2 * Math.PI * (k + 1) / sides;
            double[] p00 = {x + r0 * Math.cos(a0), y + r0 * Math.sin(a0), z0}, p01 = {x + r0 * Math.cos(a1), y + r0 * Math.sin(a1), z0};
            double[] p10 = {x + r1 * Math.cos(a0), y + r1 * Math.sin(a0), z1}, p11 = {x + r1 * Math.cos(a1), y + r1 * Math.sin(a1), z1};
            if (smooth) {
                int i0 = vertex(p00[0], p00[1], p00[2], Math.cos(a0), Math.sin(a0), slope, colour);
                int i1 = vertex(p01[0], p01[1], p01[2], Math.cos(a1), Math.sin(a1), slope, colour);
                int i2 = vertex(p11[0], p11[1], p11[2], Math.cos(a1), Math.sin(a1), slope, colour);
                int i3 = vertex(p10[0], p10[1], p10[2], Math.cos(a0), Math.sin(a0), slope, colour);
                triangle(i0, i1, i2);
                if (r1 > 0) triangle(i0, i2, i3);
            } else if (r1 > 0) {
                flatQuad(p00, p01, p11, p10, colour);
            } else {
                flatTriangle(p00, p01, p10, colour);
            }
        }
        if (r1 > 0) {
            int centre = vertex(x, y, z1, 0, 0, 1, colour);
            int first = -1, prev = -1;
            for (int k = 0; k <= sides; k++) {
                double a = 2 * Math.PI * k / sides;
                int i = vertex(x + r1 * Math.cos(a), y + r1 * Math.sin(a), z1, 0, 0, 1, colour);
                if (prev >= 0) triangle(centre, prev, i);
                prev = i;
                if (first < 0) first = i;
            }
        }
    }

    /**
     * A lump (a rock, a drift, a dune): an icosahedron once subdivided, scaled to (rx, ry, rz) about
     * (x, y, z), each corner pushed in or out by up to {@code roughness} of its radius (from
     * {@code seed}); {@code flat} gives facets, else smooth shading. Below {@code floor} it is cut flat.
     */
    public void lump(double x, double y, double z, double rx, double ry, double rz, double roughness, long seed,
                     boolean flat, double floor, float[] colour, float[] topColour) {
        lump(x, y, z, rx, ry, rz, roughness, seed, flat, floor, colour, topColour, false);
    }

    /** As above; {@code plain}: from the icosahedron itself (20 faces, not 80), for parts a few pixels across. */
    public void lump(double x, double y, double z, double rx, double ry, double rz, double roughness, long seed,
                     boolean flat, double floor, float[] colour, float[] topColour, boolean plain) {
        double[][] pts = Icosphere.points();
        int[][] faces = plain ? Icosphere.plainFaces() : Icosphere.faces();
        java.util.Random random = new java.util.Random(seed);
        double[][] w = new double[pts.length][];
        for (int k = 0; k < pts.length; k++) {
            double s = 1 + roughness * (2 * random.nextDouble() - 1);
            w[k] = new double[]{x + pts[k][0] * rx * s, y + pts[k][1] * ry * s, Math.max(floor, z + pts[k][2] * rz * s)};
        }
        if (flat) {
            for (int[] f : faces) {
                double up = (pts[f[0]][2] + pts[f[1]][2] + pts[f[2]][2]) / 3;
                flatTriangle(w[f[0]], w[f[1]], w[f[2]], up > 0.45 ? topColour : colour);
            }
            return;
        }
        int base = vertexCount();
        for (int k = 0; k < (plain ? 12 : pts.length); k++) {
            float[] c = pts[k][2] > 0.45 ? topColour : colour;
            vertex(w[k][0], w[k][1], w[k][2], pts[k][0] / rx, pts[k][1] / ry, pts[k][2] / rz, c);
        }
        for (int[] f : faces) triangle(base + f[0], base + f[1], base + f[2]);
    }
}
