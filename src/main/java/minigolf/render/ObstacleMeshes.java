package minigolf.render;

import minigolf.collision.ObstacleGeometry;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;
import minigolf.mesh.TriangleMesh;

import java.util.List;
import java.util.function.Function;

/**
 * The obstacles' meshes on the CPU (testable without GL), in world coordinates and the
 * position/normal/colour layout. The solid part is exactly what physics collides with: walls and
 * boxes from {@link ObstacleGeometry#triangles}, trunks from {@link ObstacleGeometry#treeCylinder},
 * models from their .obj triangles placed the same way. Tree crowns are decoration (not solid) and
 * kept apart, so the minimap can show only what the ball hits.
 */
public final class ObstacleMeshes {
    public static final float[] WALL_COLOR = {0.60f, 0.47f, 0.32f};
    public static final float[] BOX_COLOR = {0.68f, 0.40f, 0.30f};
    public static final float[] TRUNK_COLOR = {0.40f, 0.28f, 0.17f};
    /** Sides of the drawn trunk polygon (the physics cylinder is round; 16 sides differ by under 2%). */
    public static final int TRUNK_SEGMENTS = 16;
    /** The crown's least size relative to the trunk's radius. */
    static final double CROWN_PER_RADIUS = 2.5;

    /**
     * How a tree's crown is drawn: its size (the crown model is about that wide either side of the
     * trunk) per trunk height, and the height of its centre above the trunk's top, in crown sizes.
     */
    public record CrownStyle(double perHeight, double rise) {
        /** A course's trees: the crown sits on the trunk, high enough that the player sees the green under it. */
        public static final CrownStyle COURSE = new CrownStyle(0.32, 0.85);
        /**
         * The trees round the course: a fuller crown hung over the trunk's upper half, so that from a
         * player's eye, a metre or two up, they read as trees and not as bare poles under a lollipop.
         */
        public static final CrownStyle SURROUNDINGS = new CrownStyle(0.42, -0.3);

        /** The crown's size for a trunk this high and wide. */
        public double size(double height, double radius) {
            return Math.max(perHeight * height, CROWN_PER_RADIUS * radius);
        }
    }

    /**
     * The solid obstacles and the decorative crowns; either may have no triangles. Each obstacle's
     * triangles are one run of indices in each mesh, its piece, with its box: a pass can draw only the
     * pieces near something (the balls' shadows).
     */
    public record Built(MeshData solid, MeshData decoration, List<Piece> solidPieces, List<Piece> decorationPieces) {
    }

    /** A run of {@code count} indices from {@code first} and the box round its vertices: min x, y, z, max x, y, z. */
    public record Piece(int first, int count, float[] box) {
        /** Whether the piece's box meets {@code other} (min x, y, z, max x, y, z). */
        public boolean overlaps(float[] other) {
            return box[0] <= other[3] && box[3] >= other[0] && box[1] <= other[4] && box[4] >= other[1]
                    && box[2] <= other[5] && box[5] >= other[2];
        }
    }

    private ObstacleMeshes() {
    }

    /**
     * Builds both meshes. {@code modelMaterials} gives the colours of a model obstacle's materials
     * (see {@link MaterialLibrary#forModel}).
     */
    public static Built build(List<Obstacle> obstacles, HeightProbe ground,
                              Function<Obstacle.Model, MaterialLibrary> modelMaterials) {
        return build(obstacles, ground, modelMaterials, CrownStyle.COURSE);
    }

    /** As above, the trees' crowns drawn in this style. */
    public static Built build(List<Obstacle> obstacles, HeightProbe ground,
                              Function<Obstacle.Model, MaterialLibrary> modelMaterials, CrownStyle crownStyle) {
        Writer solid = new Writer(), crowns = new Writer();
        ModelResource crown = ModelResource.get("tree-crown");
        List<Piece> solidPieces = new java.util.ArrayList<>(), crownPieces = new java.util.ArrayList<>();
        for (Obstacle o : obstacles) {
            int solidStart = solid.vertexCount(), crownStart = crowns.vertexCount();
            if (!ObstacleGeometry.isStillSolid(o) || o instanceof Obstacle.Bumper) {
                // Gates, bumpers and moving obstacles are drawn by the course elements' own meshes.
            } else if (o instanceof Obstacle.Tree tree) {
                double[] c = ObstacleGeometry.treeCylinder(tree, ground);
                solid.append(Shapes.cylinder(c[0], c[1], c[3], c[4], c[2], TRUNK_SEGMENTS,
                        TRUNK_COLOR[0], TRUNK_COLOR[1], TRUNK_COLOR[2]));
                double size = crownStyle.size(tree.height(), c[2]);
                // Each tree turns its crown by an angle from its position, so a wood does not repeat itself.
                double turn = Math.floorMod((long) Math.floor(c[0] * 1000 + c[1] * 7919), 360);
                crowns.model(crown.mesh(), crown.materials(), c[0], c[1], c[4] + crownStyle.rise() * size, turn, size);
            } else if (o instanceof Obstacle.Model m) {
                solid.model(m.mesh(), modelMaterials.apply(m), m.position().x(), m.position().y(), m.position().z(),
                        m.rotationDeg(), m.scale());
            } else {
                float[] colour = o instanceof Obstacle.Wall ? WALL_COLOR : BOX_COLOR;
                solid.flatTriangles(ObstacleGeometry.triangles(o, ground), colour);
            }
            solid.piece(solidStart, solidPieces);
            crowns.piece(crownStart, crownPieces);
        }
        return new Built(solid.build(), crowns.build(), List.copyOf(solidPieces), List.copyOf(crownPieces));
    }

    /** A model placed as {@link Writer#model} places it, as its own mesh (the flag). */
    static MeshData placedModel(TriangleMesh mesh, MaterialLibrary materials, double x, double y, double z,
                                double rotationDeg, double scale) {
        Writer w = new Writer();
        w.model(mesh, materials, x, y, z, rotationDeg, scale);
        return w.build();
    }

    /** Appends triangles to one growing PNC vertex array (no indices shared: 0, 1, 2, ...). */
    private static final class Writer {
        private float[] v = new float[9 * 3 * 64];
        private int floats;

        private void ensure(int more) {
            if (floats + more > v.length) v = java.util.Arrays.copyOf(v, Math.max(2 * v.length, floats + more));
        }

        private void vertex(double x, double y, double z, double nx, double ny, double nz, float[] c) {
            ensure(9);
            floats = Shapes.putPnc(v, floats, x, y, z, nx, ny, nz, c[0], c[1], c[2]);
        }

        /** World triangles (9 doubles each), each lit with its own face normal; tops a little lighter. */
        void flatTriangles(double[] t, float[] colour) {
            float[] top = {Math.min(1, colour[0] * 1.18f), Math.min(1, colour[1] * 1.18f), Math.min(1, colour[2] * 1.18f)};
            for (int k = 0; k + 8 < t.length; k += 9) {
                double ux = t[k + 3] - t[k], uy = t[k + 4] - t[k + 1], uz = t[k + 5] - t[k + 2];
                double wx = t[k + 6] - t[k], wy = t[k + 7] - t[k + 1], wz = t[k + 8] - t[k + 2];
                double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
                double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
                if (l == 0) continue; // degenerate: nothing to see
                nx /= l;
                ny /= l;
                nz /= l;
                float[] c = Math.abs(nz) > 0.9 ? top : colour;
                for (int p = 0; p < 3; p++) vertex(t[k + 3 * p], t[k + 3 * p + 1], t[k + 3 * p + 2], nx, ny, nz, c);
            }
        }

        /** Indexed PNC data appended as plain triangles. */
        void append(MeshData d) {
            int stride = d.stride();
            for (int i : d.indices()) {
                ensure(stride);
                System.arraycopy(d.vertices(), i * stride, v, floats, stride);
                floats += stride;
            }
        }

        /**
         * A mesh placed as a model obstacle is: p to (x, y, z) + Rz(rotationDeg)(scale p), the same
         * arithmetic as ObstacleGeometry, coloured by each part's material.
         */
        void model(TriangleMesh mesh, MaterialLibrary materials, double x, double y, double z, double rotationDeg, double scale) {
            double a = Math.toRadians(rotationDeg), cos = Math.cos(a), sin = Math.sin(a);
            float[] p = mesh.positions(), n = mesh.normals();
            int[] idx = mesh.indices();
            float[][] colourOfTriangle = new float[idx.length / 3][];
            for (TriangleMesh.Part part : mesh.parts()) {
                float[] c = materials.color(part.material());
                for (int t = part.firstTriangle(); t < part.firstTriangle() + part.triangleCount(); t++) colourOfTriangle[t] = c;
            }
            double flip = Math.signum(scale) == 0 ? 1 : Math.signum(scale);
            for (int k = 0; k < idx.length; k++) {
                int i = idx[k];
                double px = scale * p[3 * i], py = scale * p[3 * i + 1], pz = scale * p[3 * i + 2];
                double nx = flip * n[3 * i], ny = flip * n[3 * i + 1], nz = flip * n[3 * i + 2];
                float[] c = colourOfTriangle[k / 3] != null ? colourOfTriangle[k / 3] : MaterialLibrary.DEFAULT_COLOR;
                vertex(x + cos * px - sin * py, y + sin * px + cos * py, z + pz,
                        cos * nx - sin * ny, sin * nx + cos * ny, nz, c);
            }
        }

        int vertexCount() {
            return floats / 9;
        }

        /** Adds the vertices written since {@code start} (indices are 0, 1, 2, ...) as a piece, if any. */
        void piece(int start, List<Piece> pieces) {
            int end = vertexCount();
            if (end == start) return;
            float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                    Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
            for (int i = start; i < end; i++) {
                for (int a = 0; a < 3; a++) {
                    box[a] = Math.min(box[a], v[9 * i + a]);
                    box[a + 3] = Math.max(box[a + 3], v[9 * i + a]);
                }
            }
            pieces.add(new Piece(start, end - start, box));
        }

        /**
         * The triangles as written (index k is the k-th vertex written, so pieces keep their index
         * runs), with equal vertices (position, normal, colour) stored once: a smooth model or a
         * trunk shares most of its corners, and llvmpipe shades a shared vertex once per draw.
         */
        MeshData build() {
            int n = floats / 9;
            int[] indices = new int[n];
            float[] unique = new float[floats];
            java.util.Map<VertexKey, Integer> seen = new java.util.HashMap<>(2 * n);
            int count = 0;
            for (int i = 0; i < n; i++) {
                VertexKey key = new VertexKey(v, 9 * i);
                Integer at = seen.putIfAbsent(key, count);
                if (at == null) {
                    System.arraycopy(v, 9 * i, unique, 9 * count, 9);
                    at = count++;
                }
                indices[i] = at;
            }
            return new MeshData(MeshData.PNC, java.util.Arrays.copyOf(unique, 9 * count), indices);
        }
    }

    /** The 9 floats of one written vertex, compared bit for bit. */
    private static final class VertexKey {
        private final float[] data;
        private final int offset;
        private final int hash;

        VertexKey(float[] data, int offset) {
            this.data = data;
            this.offset = offset;
            int h = 1;
            for (int k = 0; k < 9; k++) h = 31 * h + Float.floatToIntBits(data[offset + k]);
            hash = h;
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof VertexKey other)) return false;
            for (int k = 0; k < 9; k++) {
                if (Float.floatToIntBits(data[offset + k]) != Float.floatToIntBits(other.data[other.offset + k])) return false;
            }
            return true;
        }
    }
}
