package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** CPU-only: no GL needed. */
class TerrainMeshTest {
    static final int POS = 0, NORMAL = 1, COLOR = 2;

    @Test
    void tenMetreCourseIsSampledEveryFiveCentimetres() {
        TerrainMesh m = TerrainMesh.build(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN);
        assertEquals(0.05, TerrainMesh.sampleSpacing(TestCourses.lake().bounds()), 1e-12);
        assertEquals(201, m.columns());
        assertEquals(201, m.rows());
        // Surface vertex (i, j) lies on the terrain.
        int k = 37 * m.columns() + 120;
        double x = m.data().get(k, POS, 0), y = m.data().get(k, POS, 1);
        assertEquals(-5 + 120 * 0.05, x, 1e-5);
        assertEquals(-5 + 37 * 0.05, y, 1e-5);
        assertEquals(TestCourses.LAKE.height(x, y), m.data().get(k, POS, 2), 1e-5);
    }

    /** Software quality's coarser mesh: the same surface at 10 cm, and patches at that spacing land on its rows. */
    @Test
    void aCoarserSpacingSamplesTheSameSurfaceAndItsPatchesMatch() {
        TerrainMesh m = TerrainMesh.build(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN, 0.1);
        assertEquals(101, m.columns());
        assertEquals(101, m.rows());
        int k = 40 * m.columns() + 63;
        double x = m.data().get(k, POS, 0), y = m.data().get(k, POS, 1);
        assertEquals(-5 + 63 * 0.1, x, 1e-5);
        assertEquals(-5 + 40 * 0.1, y, 1e-5);
        assertEquals(TestCourses.LAKE.height(x, y), m.data().get(k, POS, 2), 1e-5);
        // A patch around y = -1 made at the same spacing starts at a whole row and repeats the built vertices.
        TerrainMesh.Patch p = TerrainMesh.surfacePatch(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN,
                m.minHeight(), m.maxHeight(), -2, -1.05, 2, -0.95, 0.1);
        int stride = m.data().stride();
        assertEquals(0, p.firstFloat() % (m.columns() * stride));
        int firstVertex = p.firstFloat() / stride;
        for (int i = 0; i < p.vertices().length; i++) {
            assertEquals(m.data().vertices()[firstVertex * stride + i], p.vertices()[i], 1e-6f, "float " + i);
        }
        assertEquals(3 * m.columns() * stride, p.vertices().length, "rows 39 to 41");
    }

    @Test
    void bigCoursesAreCappedAt256QuadsPerSide() {
        Bounds big = new Bounds(0, 0, 50, 30);
        Course c = new Course(1, "big", TestCourses.flat().terrain(), big, TestCourses.PHYSICS,
                TestCourses.flat().start(), TestCourses.flat().hole(), java.util.List.of());
        TerrainMesh m = TerrainMesh.build(c, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN);
        assertTrue(m.columns() - 1 <= TerrainMesh.MAX_QUADS && m.rows() - 1 <= TerrainMesh.MAX_QUADS,
                m.columns() + "x" + m.rows());
        assertEquals(257, m.columns());
        assertEquals(50.0 / 256, TerrainMesh.sampleSpacing(big), 1e-12);
    }

    @Test
    void normalsComeFromTheAnalyticGradient() {
        TerrainMesh m = TerrainMesh.build(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN);
        double[] s = new double[3];
        for (int k : new int[]{0, 5000, 20000, 40400}) {
            double x = m.data().get(k, POS, 0), y = m.data().get(k, POS, 1);
            TestCourses.LAKE.sample(x, y, s);
            double len = Math.sqrt(s[1] * s[1] + s[2] * s[2] + 1);
            assertEquals(-s[1] / len, m.data().get(k, NORMAL, 0), 1e-5);
            assertEquals(-s[2] / len, m.data().get(k, NORMAL, 1), 1e-5);
            assertEquals(1 / len, m.data().get(k, NORMAL, 2), 1e-5);
        }
        // On the slope east of the pond the surface rises with x: the normal leans towards -x.
        int east = 100 * m.columns() + 150; // (2.5, 0)
        assertTrue(m.data().get(east, NORMAL, 0) < -0.01);
    }

    @Test
    void greenIsLighterHighSandIsYellowLakeBedIsMud() {
        Course lake = TestCourses.lake();
        float[] low = color(lake, 1.0, 0.2), high = color(lake, -4.9, 4.9), sand = color(lake, 2.4, -2.6), bed = color(lake, 0, 0);
        assertTrue(low[1] > low[0] && low[1] > low[2], "low grass not green");
        assertTrue(high[1] > high[0] && high[1] > high[2], "high grass not green");
        assertTrue(high[1] > low[1] + 0.1f, "higher grass should be lighter: " + high[1] + " vs " + low[1]);
        assertTrue(sand[0] > 0.7f && sand[0] > sand[1] && sand[1] > sand[2] + 0.1f, "sand not sand-yellow");
        assertTrue(bed[0] > bed[2] && bed[1] < 0.45f && bed[0] < 0.5f, "lake bed not muddy");
    }

    @Test
    void heightMapGoesFromBlueUnderWaterToWhiteAtTheTop() {
        float[] c = new float[3];
        TerrainMesh.heightMapColor(-0.04, -0.04, 0.36, c);
        assertTrue(c[2] > c[0] + 0.3f && c[2] > c[1], "under water not blue");
        TerrainMesh.heightMapColor(0.01, -0.04, 0.36, c);
        assertTrue(c[1] > c[0] && c[1] > c[2], "low ground not green");
        TerrainMesh.heightMapColor(0.36, -0.04, 0.36, c);
        assertTrue(c[0] > 0.9f && c[1] > 0.9f && c[2] > 0.9f, "top not white");
    }

    @Test
    void sideWallsReachBelowTheLowestPoint() {
        TerrainMesh m = TerrainMesh.build(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN);
        float minZ = Float.MAX_VALUE;
        for (int v = 0; v < m.data().vertexCount(); v++) minZ = Math.min(minZ, m.data().get(v, POS, 2));
        assertTrue(minZ < m.minHeight() - 0.2, "no side walls: lowest vertex " + minZ);
        assertEquals(m.data().triangleCount(), 200 * 200 * 2 + 4 * 200 * 2);
    }

    @Test
    void gridFrictionIsDrawnSandWhereRoughAndGrassWhereSmooth() throws Exception {
        minigolf.physics.World w = minigolf.physics.World.load(
                java.nio.file.Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/grid-hills.json"));
        TerrainMesh m = TerrainMesh.build(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN);
        int sandy = 0, roughest = -1, smoothest = -1;
        double most = -1, least = Double.MAX_VALUE;
        for (int v = 0; v < m.columns() * m.rows(); v++) {
            double x = m.data().get(v, POS, 0), y = m.data().get(v, POS, 1);
            if (m.data().get(v, POS, 2) < 0) continue;
            double mu = w.friction().kinetic(x, y);
            if (mu > most) { most = mu; roughest = v; }
            if (mu < least) { least = mu; smoothest = v; }
            float r = m.data().get(v, COLOR, 0), g = m.data().get(v, COLOR, 1), b = m.data().get(v, COLOR, 2);
            if (mu >= TerrainMesh.SAND_FRICTION) {
                sandy++;
                assertTrue(r > g && g > b && r > 0.8, "not sand where mu_k = " + mu + ": " + r + "," + g + "," + b);
            }
        }
        assertTrue(most >= 0.45 && sandy > 50, "the sandy patch is missing: max mu_k " + most + ", " + sandy + " vertices");
        assertTrue(m.data().get(smoothest, COLOR, 1) > 1.5 * m.data().get(smoothest, COLOR, 0), "smooth ground is not green");
        assertTrue(m.data().get(roughest, COLOR, 0) > m.data().get(roughest, COLOR, 1), "roughest ground is not sand");
    }

    /**
     * A classic track's own grass is slicker (0.041) than the threshold under which the ground is
     * glazed as ice (0.06): it is drawn as plain grass, with stripes, and only ground slicker than
     * the course's own (its ice zone) gets the glaze. Before, every classic track was glazed.
     */
    @Test
    void aCourseWhoseOwnGrassIsSlickDrawsItAsGrassAndOnlySlickerGroundAsIce() {
        Course flat = TestCourses.flat();
        minigolf.course.PhysicsSettings slick = new minigolf.course.PhysicsSettings(9.81, 0.041, 0.06, 5.0,
                minigolf.course.PhysicsModel.CLASSIC);
        minigolf.course.Zone ice = new minigolf.course.Zone(new minigolf.course.Shape.Rect(new minigolf.course.Vec2(1, 1),
                new minigolf.course.Vec2(3, 3)), 0.016, 0.06);
        Course classic = new Course(Course.FORMAT, "Classic", flat.terrain(), flat.bounds(), slick, flat.start(), flat.hole(),
                java.util.List.of(ice));
        assertEquals(0.041 / TerrainMesh.GRASS_ICE_FRICTION, TerrainMesh.slickness(classic), 1e-12);
        assertEquals(1, TerrainMesh.slickness(flat));
        TerrainMesh plain = TerrainMesh.build(flat, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN);
        TerrainMesh m = TerrainMesh.build(classic, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN);
        int grass = vertexAt(m, -2, -2), glazed = vertexAt(m, 2, 2);
        for (int k = 0; k < 4; k++) {
            assertEquals(plain.data().get(grass, COLOR, k), m.data().get(grass, COLOR, k), 1e-6, "component " + k);
        }
        assertEquals(1, m.data().get(grass, COLOR, 3), 1e-6); // striped grass
        // Ice: 0.016 / (0.041 / 0.06) = 0.023, below ICE_FRICTION: fully glazed, no stripes, bluer than the grass.
        assertEquals(0, m.data().get(glazed, COLOR, 3), 1e-6);
        assertTrue(m.data().get(glazed, COLOR, 2) > m.data().get(grass, COLOR, 2) + 0.1);
    }

    private static int vertexAt(TerrainMesh m, double x, double y) {
        for (int v = 0; v < m.columns() * m.rows(); v++) {
            if (Math.abs(m.data().get(v, POS, 0) - x) < 1e-4 && Math.abs(m.data().get(v, POS, 1) - y) < 1e-4) return v;
        }
        throw new AssertionError("no vertex at " + x + ", " + y);
    }

    private static float[] color(Course c, double x, double y) {
        float[] out = new float[3];
        TerrainMesh.surfaceColor(TerrainMesh.ColorMode.GREEN, c.zones(), x, y, TestCourses.LAKE.height(x, y),
                -0.04, 0.36, c.bounds(), out);
        return out;
    }

    @Test
    void rowStartsSplitTheSurfaceIntoRowsOfQuadsBeforeTheSkirts() {
        Course course = TestCourses.lake();
        TerrainMesh m = TerrainMesh.build(course, TestCourses.LAKE, TerrainMesh.ColorMode.GREEN, 0.1);
        int[] starts = m.rowStarts();
        int quadRows = m.rows() - 1, quadColumns = m.columns() - 1;
        assertEquals(quadRows + 1, starts.length);
        assertEquals(0, starts[0]);
        // No deleted cells: every row is two triangles a quad.
        for (int j = 0; j < quadRows; j++) assertEquals(6 * quadColumns, starts[j + 1] - starts[j], "row " + j);
        // Each row's triangles lie between its two grid lines.
        var b = course.bounds();
        double dy = b.depth() / quadRows;
        MeshData d = m.data();
        for (int j : new int[]{0, quadRows / 2, quadRows - 1}) {
            for (int k = starts[j]; k < starts[j + 1]; k++) {
                double y = d.get(d.indices()[k], 0, 1);
                assertTrue(y >= b.minY() + j * dy - 1e-4 && y <= b.minY() + (j + 1) * dy + 1e-4, "row " + j + " has y " + y);
            }
        }
        // The skirts come after the surface.
        assertTrue(d.indices().length > starts[quadRows]);
    }
}
