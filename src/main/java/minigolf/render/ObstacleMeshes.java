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
 * kept apart, so the minimap can show only what the ball hits. A world's {@link Style} may round the
 * walls' tops ({@link RailShapes}: inside the same slab) and give walls and boxes a material; each
 * vertex carries its material's id as a fourth colour component ({@link #LAYOUT}).
 */
public final class ObstacleMeshes {
    public static final float[] WALL_COLOR = {0.60f, 0.47f, 0.32f};
    public static final float[] BOX_COLOR = {0.68f, 0.40f, 0.30f};
    public static final float[] TRUNK_COLOR = {0.40f, 0.28f, 0.17f};
    static final float[] CACTUS_COLOR = {0.27f, 0.47f, 0.25f};
    /** Position, normal, colour and the material's id ({@link Material#id}; meshes without it read 1, plain). */
    public static final int[] LAYOUT = {3, 3, 4};
    static final int STRIDE = 10;

    /** What a surface is made of, as materials.glsl's obstacleDetail reads it. */
    public enum Material {
        PLAIN(1), WOOD(2), PAINTED_WOOD(3), STONE(4), SANDSTONE(5),
        /** Cloth that waves in the wind (object.vert): the parts of a model whose material is named {@link #CLOTH_NAME}. */
        CLOTH(6);

        /** The .mtl material name that marks a model's waving cloth (the flag's). */
        public static final String CLOTH_NAME = "cloth";

        public final float id;

        Material(int id) {
            this.id = id;
        }

        static Material of(minigolf.theme.Theme.RailMaterial m) {
            return switch (m) {
                case WOOD -> WOOD;
                case PAINTED_WOOD -> PAINTED_WOOD;
                case STONE -> STONE;
                case SANDSTONE -> SANDSTONE;
            };
        }
    }

    /**
     * How walls and boxes look: their colours and materials, and whether walls get rounded tops.
     * {@link #CLASSIC}: the flat colours and exact square slabs of before (the editor, tests).
     */
    public record Style(float[] wallColor, float[] boxColor, Material wallMaterial, Material boxMaterial,
                        boolean roundedWalls, boolean posts, TreeLook trees) {
        public static final Style CLASSIC = new Style(WALL_COLOR, BOX_COLOR, Material.PLAIN, Material.PLAIN, false, false,
                TreeLook.CROWN);

        /** The same with square walls (the physics' slabs: a quarter of the rounded rails' triangles, for software rasterisers). */
        public Style squareWalls() {
            return new Style(wallColor, boxColor, wallMaterial, boxMaterial, false, posts, trees);
        }

        /** A world's rails and boxes. */
        public static Style of(minigolf.theme.Theme theme) {
            var m = theme.materials();
            Material rail = Material.of(m.rail());
            TreeLook trees = switch (theme.scenery().ground()) {
                case SAND -> TreeLook.CACTUS;
                case SNOW -> TreeLook.SNOWY_PINE;
                case GRASS -> TreeLook.CROWN;
            };
            return new Style(m.railColor().toArray(), m.boxColor().toArray(), rail, rail, true, true, trees);
        }
    }

    /** How a (tall) tree obstacle is drawn round its trunk, the cylinder the ball hits. */
    public enum TreeLook {
        /** The broad-leaved crown model. */
        CROWN,
        /** A saguaro: the trunk green, a domed top and arms above the ball's reach. */
        CACTUS,
        /** A conifer's tiers with snow on them. */
        SNOWY_PINE
    }

    /** Sides of the drawn trunk polygon (the physics cylinder is round; 16 sides differ by under 2%). */
    public static final int TRUNK_SEGMENTS = 16;
    /**
     * In a world's style, a "tree" lower than this (metres) is a post, a bollard or a tower stump,
     * not a tree: its cylinder is drawn in the rails' material with a domed cap, and no crown.
     */
    public static final double POST_HEIGHT = 1.0;
    /** The crown's least size relative to the trunk's radius. */
    static final double CROWN_PER_RADIUS = 2.5;

    /**
     * How a tree's crown is drawn: its size (the crown model is about that wide either side of the
     * trunk) per trunk height, the height of its centre above the trunk's top, in crown sizes, and
     * the bundled model drawn ({@code /models/NAME.obj}).
     */
    public record CrownStyle(double perHeight, double rise, String model) {
        /** A course's trees: the crown sits on the trunk, high enough that the player sees the green under it. */
        public static final CrownStyle COURSE = new CrownStyle(0.32, 0.85);
        /**
         * The trees round the course: a fuller crown hung over the trunk's upper half, so that from a
         * player's eye, a metre or two up, they read as trees and not as bare poles under a lollipop.
         */
        public static final CrownStyle SURROUNDINGS = new CrownStyle(0.42, -0.3);

        /** The broad-leaved crown, tree-crown.obj (240 triangles). */
        public CrownStyle(double perHeight, double rise) {
            this(perHeight, rise, "tree-crown");
        }

        /**
         * The same with the crown's lighter twin, tree-crown.low.obj (60 triangles, the same three
         * blobs as plain icosahedra): for software rasterisers, which pay per triangle.
         */
        public CrownStyle light() {
            return new CrownStyle(perHeight, rise, "tree-crown.low");
        }

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

    /**
     * A run of {@code count} indices from {@code first} and the box round its vertices: min x, y, z, max x, y, z;
     * {@code open}: a model that is not closed ({@link minigolf.mesh.MeshClosure}), drawn with every face.
     */
    public record Piece(int first, int count, float[] box, boolean open) {
        public Piece(int first, int count, float[] box) {
            this(first, count, box, false);
        }

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
        return build(obstacles, ground, modelMaterials, crownStyle, Style.CLASSIC);
    }

    /** As above, walls and boxes in a world's style. */
    public static Built build(List<Obstacle> obstacles, HeightProbe ground,
                              Function<Obstacle.Model, MaterialLibrary> modelMaterials, CrownStyle crownStyle, Style style) {
        Writer solid = new Writer(), crowns = new Writer();
        ModelResource crown = ModelResource.get(crownStyle.model());
        List<Piece> solidPieces = new java.util.ArrayList<>(), crownPieces = new java.util.ArrayList<>();
        for (Obstacle o : obstacles) {
            int solidStart = solid.vertexCount(), crownStart = crowns.vertexCount();
            boolean open = false;
            if (!ObstacleGeometry.isStillSolid(o) || o instanceof Obstacle.Bumper) {
                // Gates, bumpers and moving obstacles are drawn by the course elements' own meshes.
            } else if (o instanceof Obstacle.Tree tree && style.posts() && tree.height() < POST_HEIGHT) {
                double[] c = ObstacleGeometry.treeCylinder(tree, ground);
                float[] col = style.wallColor();
                solid.material = style.wallMaterial();
                solid.append(Shapes.cylinder(c[0], c[1], c[3], c[4], c[2], TRUNK_SEGMENTS, col[0], col[1], col[2]));
                // The dome is decoration on top of the cylinder the ball hits (it never reaches past its radius).
                MeshData cap = Shapes.icosphere(2, col[0] * 1.08f, col[1] * 1.08f, col[2] * 1.08f);
                solid.appendScaled(cap, c[0], c[1], c[4], c[2], c[2], c[2] * 0.45);
                solid.material = Material.PLAIN;
            } else if (o instanceof Obstacle.Tree tree && style.trees() != TreeLook.CROWN) {
                double[] c = ObstacleGeometry.treeCylinder(tree, ground);
                boolean cactus = style.trees() == TreeLook.CACTUS;
                float[] trunk = cactus ? CACTUS_COLOR : TRUNK_COLOR;
                solid.append(Shapes.cylinder(c[0], c[1], c[3], c[4], c[2], TRUNK_SEGMENTS, trunk[0], trunk[1], trunk[2]));
                minigolf.scenery.MeshWriter deco = new minigolf.scenery.MeshWriter();
                double foot = c[4] - tree.height();
                if (cactus) {
                    minigolf.scenery.PropMeshes.cactusTop(deco, c[0], c[1], foot, tree.height() + c[2], c[2],
                            Math.floorMod((long) Math.floor(c[0] * 1000 + c[1] * 7919), 1000));
                } else {
                    minigolf.scenery.PropMeshes.pineTiers(deco, c[0], c[1], foot + tree.height() * 0.25, tree.height() * 0.8, true);
                }
                crowns.append(new MeshData(MeshData.PNC, deco.vertices(), deco.indices()));
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
                open = !minigolf.mesh.MeshClosure.closed(m.mesh());
            } else if (o instanceof Obstacle.Wall w && style.roundedWalls()
                    && RailShapes.roundedWall(w, ground, (x, y, z, nx, ny, nz, shade) -> solid.vertex(x, y, z, nx, ny, nz,
                    style.wallColor()[0] * shade, style.wallColor()[1] * shade, style.wallColor()[2] * shade, style.wallMaterial()))) {
                // written by RailShapes
            } else {
                boolean wall = o instanceof Obstacle.Wall;
                solid.material = wall ? style.wallMaterial() : style.boxMaterial();
                solid.flatTriangles(ObstacleGeometry.triangles(o, ground), wall ? style.wallColor() : style.boxColor());
                solid.material = Material.PLAIN;
            }
            solid.piece(solidStart, solidPieces, open);
            crowns.piece(crownStart, crownPieces, false);
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

    /** Appends triangles to one growing vertex array in {@link #LAYOUT} (no indices shared: 0, 1, 2, ...). */
    private static final class Writer {
        private float[] v = new float[STRIDE * 3 * 64];
        private int floats;
        /** The material of what {@link #flatTriangles}, {@link #append} and {@link #model} write. */
        Material material = Material.PLAIN;

        private void ensure(int more) {
            if (floats + more > v.length) v = java.util.Arrays.copyOf(v, Math.max(2 * v.length, floats + more));
        }

        private void vertex(double x, double y, double z, double nx, double ny, double nz, float[] c) {
            vertex(x, y, z, nx, ny, nz, c[0], c[1], c[2], material);
        }

        void vertex(double x, double y, double z, double nx, double ny, double nz, float r, float g, float b, Material m) {
            ensure(STRIDE);
            floats = Shapes.putPnc(v, floats, x, y, z, nx, ny, nz, r, g, b);
            v[floats++] = m.id;
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

        /** Indexed PNC data about the origin, scaled by (sx, sy, sz) and moved to (x, y, z), its upper half only (a dome). */
        void appendScaled(MeshData d, double x, double y, double z, double sx, double sy, double sz) {
            int stride = d.stride();
            float[] s = d.vertices();
            int[] idx = d.indices();
            for (int t = 0; t + 2 < idx.length; t += 3) {
                boolean upper = true;
                for (int k = 0; k < 3; k++) upper &= s[idx[t + k] * stride + 2] >= -1e-6;
                if (!upper) continue;
                for (int k = 0; k < 3; k++) {
                    int i = idx[t + k] * stride;
                    vertex(x + sx * s[i], y + sy * s[i + 1], z + sz * s[i + 2], s[i + 3] / sx, s[i + 4] / sy, s[i + 5] / sz,
                            s[i + 6], s[i + 7], s[i + 8], material);
                }
            }
        }

        /** Indexed PNC data appended as plain triangles. */
        void append(MeshData d) {
            int stride = d.stride();
            float[] s = d.vertices();
            for (int i : d.indices()) {
                int k = i * stride;
                vertex(s[k], s[k + 1], s[k + 2], s[k + 3], s[k + 4], s[k + 5], s[k + 6], s[k + 7], s[k + 8], material);
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
            boolean[] cloth = new boolean[idx.length / 3];
            for (TriangleMesh.Part part : mesh.parts()) {
                float[] c = materials.color(part.material());
                boolean waves = Material.CLOTH_NAME.equals(part.material());
                for (int t = part.firstTriangle(); t < part.firstTriangle() + part.triangleCount(); t++) {
                    colourOfTriangle[t] = c;
                    cloth[t] = waves;
                }
            }
            double flip = Math.signum(scale) == 0 ? 1 : Math.signum(scale);
            for (int k = 0; k < idx.length; k++) {
                int i = idx[k];
                double px = scale * p[3 * i], py = scale * p[3 * i + 1], pz = scale * p[3 * i + 2];
                double nx = flip * n[3 * i], ny = flip * n[3 * i + 1], nz = flip * n[3 * i + 2];
                float[] c = colourOfTriangle[k / 3] != null ? colourOfTriangle[k / 3] : MaterialLibrary.DEFAULT_COLOR;
                vertex(x + cos * px - sin * py, y + sin * px + cos * py, z + pz,
                        cos * nx - sin * ny, sin * nx + cos * ny, nz, c[0], c[1], c[2], cloth[k / 3] ? Material.CLOTH : material);
            }
        }

        int vertexCount() {
            return floats / STRIDE;
        }

        /** Adds the vertices written since {@code start} (indices are 0, 1, 2, ...) as a piece, if any. */
        void piece(int start, List<Piece> pieces, boolean open) {
            int end = vertexCount();
            if (end == start) return;
            float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                    Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
            for (int i = start; i < end; i++) {
                for (int a = 0; a < 3; a++) {
                    box[a] = Math.min(box[a], v[STRIDE * i + a]);
                    box[a + 3] = Math.max(box[a + 3], v[STRIDE * i + a]);
                }
            }
            pieces.add(new Piece(start, end - start, box, open));
        }

        /**
         * The triangles as written (index k is the k-th vertex written, so pieces keep their index
         * runs), with equal vertices (position, normal, colour) stored once: a smooth model or a
         * trunk shares most of its corners, and llvmpipe shades a shared vertex once per draw.
         */
        MeshData build() {
            int n = floats / STRIDE;
            int[] indices = new int[n];
            float[] unique = new float[floats];
            java.util.Map<VertexKey, Integer> seen = new java.util.HashMap<>(2 * n);
            int count = 0;
            for (int i = 0; i < n; i++) {
                VertexKey key = new VertexKey(v, STRIDE * i);
                Integer at = seen.putIfAbsent(key, count);
                if (at == null) {
                    System.arraycopy(v, STRIDE * i, unique, STRIDE * count, STRIDE);
                    at = count++;
                }
                indices[i] = at;
            }
            return new MeshData(LAYOUT, java.util.Arrays.copyOf(unique, STRIDE * count), indices);
        }
    }

    /** The floats of one written vertex, compared bit for bit. */
    private static final class VertexKey {
        private final float[] data;
        private final int offset;
        private final int hash;

        VertexKey(float[] data, int offset) {
            this.data = data;
            this.offset = offset;
            int h = 1;
            for (int k = 0; k < STRIDE; k++) h = 31 * h + Float.floatToIntBits(data[offset + k]);
            hash = h;
        }

        @Override
        public int hashCode() {
            return hash;
        }

        @Override
        public boolean equals(Object o) {
            if (!(o instanceof VertexKey other)) return false;
            for (int k = 0; k < STRIDE; k++) {
                if (Float.floatToIntBits(data[offset + k]) != Float.floatToIntBits(other.data[other.offset + k])) return false;
            }
            return true;
        }
    }
}
