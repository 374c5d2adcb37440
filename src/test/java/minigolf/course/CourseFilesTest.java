package minigolf.course;

import minigolf.expr.Expression;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.*;

/** Every course in courses/ loads, is playable and round-trips; the lake course is exactly the manual's. */
class CourseFilesTest {
    static Path coursesDir() {
        String dir = System.getProperty("minigolf.projectDir");
        return Paths.get(dir != null ? dir : System.getProperty("user.dir")).resolve("courses");
    }

    static List<Path> courseFiles() throws IOException {
        try (Stream<Path> s = Files.list(coursesDir())) {
            return s.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        }
    }

    /**
     * Heights for the placement check: the expression itself, or for a grid the lowest node of the
     * 4x4 bicubic stencil around the point (conservative: the real bicubic interpolation lives in
     * minigolf.terrain, outside this package).
     */
    static HeightProbe probe(TerrainSpec spec) {
        if (spec instanceof TerrainSpec.HeightExpression e) {
            Expression expr = Expression.parse(e.source());
            return expr::evaluate;
        }
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) spec;
        return (x, y) -> {
            int i = (int) Math.floor((x - g.origin().x()) / g.spacing());
            int j = (int) Math.floor((y - g.origin().y()) / g.spacing());
            double min = Double.POSITIVE_INFINITY;
            for (int jj = j - 1; jj <= j + 2; jj++) {
                for (int ii = i - 1; ii <= i + 2; ii++) {
                    int cj = Math.max(0, Math.min(g.rows() - 1, jj)), ci = Math.max(0, Math.min(g.columns() - 1, ii));
                    min = Math.min(min, g.heights()[cj][ci]);
                }
            }
            return min;
        };
    }

    @Test
    void theExpectedCoursesAreThere() throws IOException {
        List<String> names = courseFiles().stream().map(p -> p.getFileName().toString()).toList();
        assertTrue(names.containsAll(List.of("flat.json", "plane.json", "lake.json", "sine-hills.json", "sine-cross.json",
                "sand.json", "grid-hills.json", "grid-256.json")), names.toString());
        String readme = Files.readString(coursesDir().resolve("README.md"));
        for (String n : names) assertTrue(readme.contains("`" + n + "`"), "README describes " + n);
    }

    @Test
    void everyCourseLoadsWithStartAndHoleOnDryLandAndPlayableValues() throws IOException, CourseException {
        for (Path f : courseFiles()) {
            Course c = CourseLoader.load(f, CourseFilesTest::probe);
            String n = f.getFileName().toString();
            Hole h = c.hole();
            Bounds b = c.bounds();
            // the whole cup inside the bounds and on dry land
            assertTrue(h.position().x() - h.radius() >= b.minX() && h.position().x() + h.radius() <= b.maxX()
                    && h.position().y() - h.radius() >= b.minY() && h.position().y() + h.radius() <= b.maxY(), n);
            HeightProbe p = probe(c.terrain());
            for (int k = 0; k < 16; k++) {
                double a = 2 * Math.PI * k / 16;
                assertTrue(p.height(h.position().x() + h.radius() * Math.cos(a), h.position().y() + h.radius() * Math.sin(a)) >= 0, n);
            }
            assertTrue(h.radius() >= 0.05 && h.radius() <= 0.15, n + " hole radius");
            assertTrue(c.physics().maxSpeed() >= 3 && c.physics().maxSpeed() <= 5, n + " maxSpeed");
            assertTrue(c.physics().kineticFriction() >= 0.05 && c.physics().kineticFriction() <= 0.15, n + " grass friction");
            assertTrue(c.start().distanceTo(h.position()) > 3, n + " start far from the hole");
            assertEquals(c, CourseLoader.parse(CourseWriter.toJson(c), n), n + " round trip");
        }
    }

    @Test
    void lakeIsTheManualsTestCourse() throws CourseException {
        Course c = CourseLoader.load(coursesDir().resolve("lake.json"));
        assertEquals(new Course(1, "Lake", new TerrainSpec.HeightExpression("0.4*(0.9-exp(-(x^2+y^2)/8))"),
                new Bounds(-5, -5, 5, 5), new PhysicsSettings(9.81, 0.08, 0.2, 5.0, PhysicsModel.CLASSIC),
                new Vec2(-3, 0), new Hole(new Vec2(4, 1), 0.15, HoleRule.REST, null), List.of()), c);
        HeightProbe h = probe(c.terrain());
        assertTrue(h.height(0, 0) < 0, "the lake is in the middle");
        assertEquals(0.4 * (0.9 - Math.exp(-9.0 / 8)), h.height(-3, 0), 1e-15);
    }

    @Test
    void sandCourseHasTwoSandTrapsAndAFastStrip() throws CourseException {
        Course c = CourseLoader.load(coursesDir().resolve("sand.json"));
        assertEquals(3, c.zones().size());
        assertInstanceOf(Shape.Rect.class, c.zones().get(0).shape());
        assertInstanceOf(Shape.Circle.class, c.zones().get(1).shape());
        assertInstanceOf(Shape.Polygon.class, c.zones().get(2).shape());
        for (Zone z : c.zones().subList(0, 2)) assertTrue(z.kineticFriction() >= 0.25 && z.kineticFriction() <= 0.8);
        assertTrue(c.zones().get(2).kineticFriction() < c.physics().kineticFriction());
        for (Zone z : c.zones()) {
            assertFalse(z.shape().contains(c.start().x(), c.start().y()));
            assertFalse(z.shape().contains(c.hole().position().x(), c.hole().position().y()));
        }
    }

    @Test
    void gridHillsHasAPondAndASandyPatch() throws CourseException {
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) CourseLoader.load(coursesDir().resolve("grid-hills.json")).terrain();
        assertEquals(41, g.columns());
        assertEquals(41, g.rows());
        assertEquals(0.25, g.spacing());
        assertTrue(Stream.of(g.heights()).flatMapToDouble(java.util.Arrays::stream).min().orElseThrow() < 0, "a pond");
        assertTrue(Stream.of(g.kineticFriction()).flatMapToDouble(java.util.Arrays::stream).max().orElseThrow() >= 0.25, "sand");
        assertNotNull(g.staticFriction());
    }

    @Test
    void grid256IsTheBenchmarkGrid() throws CourseException {
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) CourseLoader.load(coursesDir().resolve("grid-256.json")).terrain();
        assertEquals(256, g.columns());
        assertEquals(256, g.rows());
        assertEquals(0.05, g.spacing());
        assertTrue(Stream.of(g.heights()).flatMapToDouble(java.util.Arrays::stream).min().orElseThrow() > 0, "all dry");
        for (double[] row : g.heights()) {
            for (double v : row) assertEquals(v, Math.round(v * 1e4) / 1e4, 0.0, "4 decimals");
        }
    }

    @Test
    void theFullExampleInTheFormatDocumentLoads() throws IOException, CourseException {
        String doc = Files.readString(coursesDir().resolveSibling("docs").resolve("course-format.md"));
        int from = doc.indexOf("## Full example");
        int start = doc.indexOf("```json\n", from) + "```json\n".length();
        String json = doc.substring(start, doc.indexOf("```", start));
        Course c = CourseLoader.parse(json, "docs/course-format.md", CourseFilesTest::probe);
        assertEquals("Lake", c.name());
        assertEquals(3, c.zones().size());
        assertEquals(c, CourseLoader.parse(CourseWriter.toJson(c), "again"));
    }
}
