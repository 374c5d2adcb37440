package minigolf.render;

import minigolf.collision.ObstacleGeometry;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The obstacles' meshes on the CPU: exactly the triangles physics collides with (no GL needed). */
class ObstacleMeshesTest {
    static final double H = 0.1;

    static ObstacleMeshes.Built build(List<Obstacle> obstacles) {
        return ObstacleMeshes.build(obstacles, (x, y) -> 0.1 + 0.05 * x, m -> MaterialLibrary.empty());
    }

    /** The drawn triangles' positions, in order, must be physics' triangles rounded to float. */
    static void assertSamePositions(double[] physics, MeshData drawn) {
        assertEquals(physics.length / 9, drawn.triangleCount());
        for (int t = 0; t < drawn.triangleCount(); t++) {
            for (int corner = 0; corner < 3; corner++) {
                int vertex = drawn.indices()[3 * t + corner];
                for (int c = 0; c < 3; c++) {
                    assertEquals((float) physics[9 * t + 3 * corner + c], drawn.get(vertex, 0, c), 1e-6,
                            "triangle " + t + " corner " + corner);
                }
            }
        }
    }

    @Test
    void wallsAndBoxesAreDrawnWithPhysicsTrianglesAndFaceNormals() {
        Obstacle wall = new Obstacle.Wall(new Vec2(-1, 0.5), new Vec2(2, 1.5), 0.1, 0.3, 0.7);
        Obstacle box = new Obstacle.Box(new Vec3(1, 1, 0), new Vec3(1.4, 1.6, 0.5), 30, 0.7);
        ObstacleMeshes.Built built = build(List.of(wall, box));
        double[] physics = ObstacleGeometry.triangles(wall, (x, y) -> 0.1 + 0.05 * x);
        double[] boxPhysics = ObstacleGeometry.triangles(box, (x, y) -> 0.1 + 0.05 * x);
        double[] both = new double[physics.length + boxPhysics.length];
        System.arraycopy(physics, 0, both, 0, physics.length);
        System.arraycopy(boxPhysics, 0, both, physics.length, boxPhysics.length);
        assertSamePositions(both, built.solid());
        assertEquals(24, built.solid().triangleCount()); // two cuboids of 12 triangles
        assertEquals(0, built.decoration().triangleCount());
        // Every normal is unit length and perpendicular to its triangle's edges.
        MeshData d = built.solid();
        for (int t = 0; t < d.triangleCount(); t++) {
            int a = d.indices()[3 * t], b = d.indices()[3 * t + 1];
            double nx = d.get(a, 1, 0), ny = d.get(a, 1, 1), nz = d.get(a, 1, 2);
            assertEquals(1, Math.sqrt(nx * nx + ny * ny + nz * nz), 1e-5);
            double ex = d.get(b, 0, 0) - d.get(a, 0, 0), ey = d.get(b, 0, 1) - d.get(a, 0, 1), ez = d.get(b, 0, 2) - d.get(a, 0, 2);
            assertEquals(0, nx * ex + ny * ey + nz * ez, 1e-5);
        }
        // The wall's sides in the wall colour, the box's in the box colour.
        assertEquals(ObstacleMeshes.WALL_COLOR[0], d.get(d.indices()[3 * 4], 2, 0), 1e-6); // side face of the wall
        assertEquals(ObstacleMeshes.BOX_COLOR[0], d.get(d.indices()[3 * 16], 2, 0), 1e-6); // side face of the box
    }

    @Test
    void aModelIsPlacedLikePhysicsPlacesItAndColouredByItsMaterials() throws Exception {
        TriangleMesh mesh = ObjParser.parse("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                + "usemtl red\nf 1 2 3\nusemtl blue\nf 1 2 4\nusemtl nothing\nf 1 3 4\n");
        Obstacle.Model model = new Obstacle.Model("m.obj", new Vec3(2, -1, 0.3), 90, 2, 0.5, mesh);
        MaterialLibrary mtl = MaterialLibrary.parse("# colours\nnewmtl red\nKa 0 0 0\nKd 0.9 0.1 0.1\nillum 2\n"
                + "newmtl blue\nKd 0.1 0.2 0.8\nmap_Kd stone.png\nnewmtl broken\nKd x y z\n");
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.of(model), (x, y) -> 0, m -> mtl);
        MeshData d = built.solid();
        assertSamePositions(ObstacleGeometry.triangles(model, (x, y) -> 0), d);
        // The first vertex (model origin) lands at the position; model x (1, 0, 0) turned 90 degrees and doubled: (2, -1 + 2, 0.3).
        assertEquals(2f, d.get(1, 0, 0), 1e-6);
        assertEquals(1f, d.get(1, 0, 1), 1e-6);
        assertEquals(0.9f, d.get(0, 2, 0), 1e-6);
        assertEquals(0.8f, d.get(3, 2, 2), 1e-6);
        assertArrayEquals(MaterialLibrary.DEFAULT_COLOR, new float[]{d.get(6, 2, 0), d.get(6, 2, 1), d.get(6, 2, 2)});
        assertFalse(mtl.has("broken"), "a Kd that is not numbers is skipped");
        // Normals turn with the model: 90 degrees about z takes (nx, ny, nz) to (-ny, nx, nz).
        float[] n = mesh.normals();
        assertEquals(-n[4], d.get(1, 1, 0), 1e-6);
        assertEquals(n[3], d.get(1, 1, 1), 1e-6);
        assertEquals(n[5], d.get(1, 1, 2), 1e-6);
    }

    @Test
    void aTreeIsItsCollisionCylinderWithACrownOnTop() {
        Obstacle.Tree tree = new Obstacle.Tree(new Vec2(1, 2), 0.15, 2.0, 0.6);
        ObstacleMeshes.Built built = build(List.of(tree));
        double[] c = ObstacleGeometry.treeCylinder(tree, (x, y) -> 0.1 + 0.05 * x);
        MeshData trunk = built.solid();
        double minZ = Double.MAX_VALUE, maxZ = -Double.MAX_VALUE;
        for (int v = 0; v < trunk.vertexCount(); v++) {
            double dx = trunk.get(v, 0, 0) - c[0], dy = trunk.get(v, 0, 1) - c[1], r = Math.hypot(dx, dy);
            assertTrue(r < 1e-6 || Math.abs(r - c[2]) < 1e-6, "trunk vertex at radius " + r);
            minZ = Math.min(minZ, trunk.get(v, 0, 2));
            maxZ = Math.max(maxZ, trunk.get(v, 0, 2));
        }
        assertEquals(c[3], minZ, 1e-6);
        assertEquals(c[4], maxZ, 1e-6);
        assertEquals(2.0 + 0.1 + 0.05, maxZ, 1e-6); // h(1, 2) + height
        MeshData crown = built.decoration();
        assertEquals(240, crown.triangleCount());
        double size = ObstacleMeshes.CrownStyle.COURSE.size(2.0, 0.15), low = Double.MAX_VALUE;
        for (int v = 0; v < crown.vertexCount(); v++) {
            low = Math.min(low, crown.get(v, 0, 2));
            assertTrue(Math.hypot(crown.get(v, 0, 0) - 1, crown.get(v, 0, 1) - 2) < 1.3 * size, "crown stays over the trunk");
            assertTrue(crown.get(v, 1, 1) > 0.2f || crown.get(v, 2, 1) > crown.get(v, 2, 0), "crowns are leaf green");
        }
        assertTrue(low < maxZ && low > maxZ - 0.2 * size, "the crown sits on the trunk's top: lowest " + low + ", top " + maxZ);
    }

    /**
     * The software tier's crown (tree-crown.low.obj, 60 triangles) takes the crown's leaf colours
     * from the library its mtllib names (tree-crown.mtl) and fills about the same space: its box
     * within 15% of the full crown's on every side, in both styles.
     */
    @Test
    void theLightCrownIsTheSameTreeWithAQuarterOfTheTriangles() {
        Obstacle.Tree tree = new Obstacle.Tree(new Vec2(0, 0), 0.18, 4.0, 0);
        for (ObstacleMeshes.CrownStyle style : List.of(ObstacleMeshes.CrownStyle.COURSE, ObstacleMeshes.CrownStyle.SURROUNDINGS)) {
            MeshData full = ObstacleMeshes.build(List.of(tree), (x, y) -> 0, m -> null, style).decoration();
            MeshData light = ObstacleMeshes.build(List.of(tree), (x, y) -> 0, m -> null, style.light()).decoration();
            assertEquals(240, full.triangleCount());
            assertEquals(60, light.triangleCount());
            assertEquals("tree-crown.low", style.light().model());
            double[] a = box(full), b = box(light);
            double size = style.size(4.0, 0.18);
            for (int k = 0; k < 6; k++) assertEquals(a[k], b[k], 0.15 * size, "box side " + k + " of " + style);
            java.util.Set<String> fullColours = colours(full), lightColours = colours(light);
            assertEquals(java.util.Set.of("0.20 0.42 0.16", "0.30 0.52 0.20"), fullColours, "tree-crown.mtl's leaves");
            assertEquals(fullColours, lightColours, "the twin reads the crown's library, not grey defaults");
        }
    }

    private static double[] box(MeshData d) {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int v = 0; v < d.vertexCount(); v++) {
            for (int k = 0; k < 3; k++) {
                b[k] = Math.min(b[k], d.get(v, 0, k));
                b[k + 3] = Math.max(b[k + 3], d.get(v, 0, k));
            }
        }
        return b;
    }

    private static java.util.Set<String> colours(MeshData d) {
        java.util.Set<String> s = new java.util.TreeSet<>();
        for (int v = 0; v < d.vertexCount(); v++) s.add(String.format(java.util.Locale.ROOT, "%.2f %.2f %.2f", d.get(v, 2, 0), d.get(v, 2, 1), d.get(v, 2, 2)));
        return s;
    }

    @Test
    void treesRoundTheCourseHangTheirCrownOverTheTrunksUpperHalf() {
        // A 4 m tree on flat ground: the course style leaves the whole trunk bare under the crown (a
        // lollipop from a player's eye); the surroundings' style covers its upper half.
        Obstacle.Tree tree = new Obstacle.Tree(new Vec2(0, 0), 0.18, 4.0, 0);
        for (ObstacleMeshes.CrownStyle style : List.of(ObstacleMeshes.CrownStyle.COURSE, ObstacleMeshes.CrownStyle.SURROUNDINGS)) {
            MeshData crown = ObstacleMeshes.build(List.of(tree), (x, y) -> 0, m -> MaterialLibrary.empty(), style).decoration();
            double low = Double.MAX_VALUE, high = -Double.MAX_VALUE, wide = 0;
            for (int v = 0; v < crown.vertexCount(); v++) {
                low = Math.min(low, crown.get(v, 0, 2));
                high = Math.max(high, crown.get(v, 0, 2));
                wide = Math.max(wide, Math.hypot(crown.get(v, 0, 0), crown.get(v, 0, 1)));
            }
            if (style == ObstacleMeshes.CrownStyle.COURSE) {
                assertTrue(low > 3.6, "a course tree's crown starts at its trunk's top: lowest " + low);
            } else {
                assertTrue(low > 1.6 && low < 2.4, "bare trunk about half the tree: crown from " + low + " m");
                assertTrue(high > 4.5 && high < 5.5, "the crown rises above the trunk: top " + high);
                assertTrue(wide > 1.3 && wide < 1.9, "a full crown, about 0.4 of the height either side: " + wide);
            }
        }
    }

    @Test
    void theWindmillGetsItsMtlColoursFromTheShippedCourse() throws Exception {
        World w = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "windmill.json"));
        Obstacle.Model mill = (Obstacle.Model) w.course().obstacles().get(0);
        // No course folder: found on the classpath under /courses/models/.
        MaterialLibrary mtl = MaterialLibrary.forModel(mill.file(), mill.mesh(), null);
        assertArrayEquals(new float[]{0.92f, 0.90f, 0.84f}, mtl.color("whitewash"));
        assertArrayEquals(new float[]{0.55f, 0.38f, 0.20f}, mtl.color("thatch"));
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.of(mill), w.terrain()::height,
                m -> MaterialLibrary.forModel(m.file(), m.mesh(), null));
        assertEquals(mill.mesh().triangleCount(), built.solid().triangleCount());
        assertSamePositions(ObstacleGeometry.triangles(mill, w.terrain()::height), built.solid());
        // A missing library gives the default colour, not a failure.
        MaterialLibrary none = MaterialLibrary.forModel("nowhere/x.obj", mill.mesh(), Path.of("/nonexistent"));
        assertArrayEquals(MaterialLibrary.DEFAULT_COLOR, none.color("whitewash"));
    }

    @Test
    void eachObstacleIsOnePieceWithItsBox() {
        Obstacle wall = new Obstacle.Wall(new Vec2(-1, 0.5), new Vec2(2, 1.5), 0.1, 0.3, 0.7);
        Obstacle tree = new Obstacle.Tree(new Vec2(3, -2), 0.15, 2.0, 0.6);
        Obstacle box = new Obstacle.Box(new Vec3(1, 1, 0), new Vec3(1.4, 1.6, 0.5), 30, 0.7);
        ObstacleMeshes.Built built = build(List.of(wall, tree, box));
        List<ObstacleMeshes.Piece> solid = built.solidPieces();
        assertEquals(3, solid.size());
        // The pieces tile the solid mesh's indices in order.
        assertEquals(0, solid.get(0).first());
        assertEquals(solid.get(0).count(), solid.get(1).first());
        assertEquals(solid.get(1).first() + solid.get(1).count(), solid.get(2).first());
        assertEquals(built.solid().indices().length, solid.get(2).first() + solid.get(2).count());
        assertEquals(36, solid.get(0).count()); // the wall: 12 triangles
        // The wall's box: its ends reach half the thickness past each end and to each side (direction
        // (3, 1)/sqrt 10), from the ground (0.1 + 0.05 x) up 0.3.
        float[] w = solid.get(0).box();
        assertEquals(-1 - 0.05 * (3 + 1) / Math.sqrt(10), w[0], 1e-5);
        assertEquals(0.1 + 0.05 * 2 + 0.3, w[5], 0.06);
        // Only the tree has a crown, above its trunk.
        assertEquals(1, built.decorationPieces().size());
        float[] crown = built.decorationPieces().get(0).box();
        assertTrue(crown[0] < 3 && crown[3] > 3 && crown[1] < -2 && crown[4] > -2, java.util.Arrays.toString(crown));
        // Overlap tests: a box round the tree's foot meets the trunk, not the wall.
        float[] nearTree = {2.9f, -2.1f, 0f, 3.1f, -1.9f, 0.5f};
        assertTrue(solid.get(1).overlaps(nearTree));
        assertFalse(solid.get(0).overlaps(nearTree));
        assertFalse(solid.get(2).overlaps(nearTree));
    }

    @Test
    void equalCornersAreStoredOnce() {
        // A wall is 6 flat faces: 12 triangles, 36 indices, 4 distinct corners a face (each triangle's
        // normal is computed from its own edges, so a face's two may differ in the last bit: up to 2 more).
        Obstacle wall = new Obstacle.Wall(new Vec2(-1, 0.5), new Vec2(2, 1.5), 0.1, 0.3, 0.7);
        MeshData w = build(List.of(wall)).solid();
        assertEquals(36, w.indices().length);
        int corners = w.vertices().length / w.stride();
        assertTrue(corners >= 24 && corners <= 30, "wall corners stored: " + corners);
        // A smooth trunk shares more: its side and cap corners serve several triangles each.
        Obstacle tree = new Obstacle.Tree(new Vec2(3, -2), 0.15, 2.0, 0.6);
        MeshData t = build(List.of(tree)).solid();
        assertTrue(t.vertices().length / t.stride() * 2 < t.indices().length,
                "trunk corners not shared: " + t.vertices().length / t.stride() + " for " + t.indices().length + " indices");
        for (int index : t.indices()) assertTrue(index >= 0 && index < t.vertices().length / t.stride());
    }

    @Test
    void boxesOffScreenAreCulledAndBoxesBehindTheEyeKept() {
        FrameContext frame = new FrameContext(FrameContext.Sun.afternoon());
        // The eye 6 m south of the origin, 4 m up, looking at it.
        OrbitCamera cam = new OrbitCamera(new org.joml.Vector3f(0, 0, 0), (float) Math.toRadians(-90), (float) Math.toRadians(34), 7f);
        frame.update(cam, 800, 450, 0f);
        int[] all = {0, 0, 800, 450};
        assertTrue(ObstaclesPass.onScreen(new float[]{-0.2f, -0.2f, 0f, 0.2f, 0.2f, 0.5f}, frame, all));
        // Far to the east, beyond the 45-degree view's edge.
        assertFalse(ObstaclesPass.onScreen(new float[]{30f, -0.2f, 0f, 30.4f, 0.2f, 0.5f}, frame, all));
        // Straddling the eye's plane: kept, whatever its projection says.
        org.joml.Vector3f eye = cam.eye();
        assertTrue(ObstaclesPass.onScreen(new float[]{eye.x - 1, eye.y - 1, 0f, eye.x + 1, eye.y + 1, 8f}, frame, all));
        // In view but outside a small rectangle in the image's top-left corner.
        assertFalse(ObstaclesPass.onScreen(new float[]{-0.2f, -0.2f, 0f, 0.2f, 0.2f, 0.5f}, frame, new int[]{0, 400, 40, 50}));
    }
}
