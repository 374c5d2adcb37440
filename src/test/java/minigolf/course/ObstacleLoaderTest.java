package minigolf.course;

import static minigolf.course.CourseLoaderTest.SRC;
import static minigolf.course.CourseLoaderTest.edit;
import static minigolf.course.CourseLoaderTest.error;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The obstacles and the ball/flight physics fields: parsing, defaults, errors and the writer's round trip. */
class ObstacleLoaderTest {
    static final String TETRA = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

    static String withObstacles(String obstacles) {
        return edit("\"obstacles\": []", "\"obstacles\": [" + obstacles + "]");
    }

    @Test
    void readsEveryKindWithDefaults() throws CourseException {
        Course c = CourseLoader.parse(withObstacles(String.join(", ",
                "{ \"type\": \"wall\", \"from\": [0, 0], \"to\": [1, 0], \"thickness\": 0, \"height\": 0.1 }",
                "{ \"type\": \"tree\", \"position\": [2, 2], \"radius\": 0.2, \"height\": 2, \"restitution\": 0.5 }",
                "{ \"type\": \"box\", \"min\": [0, 1, 0], \"max\": [1, 2, 0.5], \"rotationDeg\": 30 }")), SRC);
        assertEquals(List.of(new Obstacle.Wall(new Vec2(0, 0), new Vec2(1, 0), 0, 0.1, 0.7),
                new Obstacle.Tree(new Vec2(2, 2), 0.2, 2, 0.5),
                new Obstacle.Box(new Vec3(0, 1, 0), new Vec3(1, 2, 0.5), 30, 0.7)), c.obstacles());
        PhysicsSettings p = c.physics();
        assertEquals(0.02135, p.ballRadius());
        assertEquals(0.04593, p.ballMass());
        assertEquals(0.5, p.dragCoefficient());
        assertEquals(1.2, p.airDensity());
        assertNull(p.groundRestitution());
        // k = Cd rho pi r^2 / (2 m)
        assertEquals(0.5 * 1.2 * Math.PI * 0.02135 * 0.02135 / (2 * 0.04593), p.dragFactor(), 1e-15);
    }

    /** One box per wall tile, as the classic online game's tracks convert: the largest of 334 plain tracks has 1,788. */
    @Test
    void aClassicTrackDrawnTileByTileFitsTheObstacleLimit() throws CourseException {
        assertEquals(1_788, CourseLoader.parse(withObstacles(tiles(1_788)), "x.json").obstacles().size());
        assertEquals(2_500, CourseLoader.parse(withObstacles(tiles(2_500)), "x.json").obstacles().size());
        CourseException e = org.junit.jupiter.api.Assertions.assertThrows(CourseException.class,
                () -> CourseLoader.parse(withObstacles(tiles(2_501)), "x.json"));
        assertEquals("x.json: obstacles: too many obstacles: 2501 (the limit is 2500)", e.getMessage());
    }

    /** {@code n} boxes of 0.1 m on a 50-wide grid of tiles. */
    private static String tiles(int n) {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < n; k++) {
            double x = 0.1 * (k % 50) - 2.5, y = 0.1 * (k / 50) - 2.5;
            if (k > 0) sb.append(", ");
            sb.append(String.format(java.util.Locale.ROOT, "{\"type\": \"box\", \"min\": [%.1f, %.1f, 0], \"max\": [%.1f, %.1f, 0.1]}",
                    x, y, x + 0.1, y + 0.1));
        }
        return sb.toString();
    }

    @Test
    void badObstacleDataGivesOneLineErrors() {
        assertEquals("courses/x.json: obstacles[0]: from and to are the same point and thickness is 0: the wall has no extent",
                error(withObstacles("{ \"type\": \"wall\", \"from\": [1, 1], \"to\": [1, 1], \"thickness\": 0, \"height\": 0.1 }")));
        assertEquals("courses/x.json: obstacles[0].radius: must be > 0, got -0.2",
                error(withObstacles("{ \"type\": \"tree\", \"position\": [2, 2], \"radius\": -0.2, \"height\": 2 }")));
        assertEquals("courses/x.json: obstacles[0].restitution: must be between 0 and 2, got 2.5",
                error(withObstacles("{ \"type\": \"tree\", \"position\": [2, 2], \"radius\": 0.2, \"height\": 2, \"restitution\": 2.5 }")));
        assertEquals("courses/x.json: obstacles[0].type: expected one of wall, tree, box, model, bumper, gate, got \"rock\"",
                error(withObstacles("{ \"type\": \"rock\" }")));
        assertEquals("courses/x.json: obstacles[0]: min must be < max in all three axes, got min (0, 0, 1), max (1, 1, 1)",
                error(withObstacles("{ \"type\": \"box\", \"min\": [0, 0, 1], \"max\": [1, 1, 1] }")));
        assertEquals("courses/x.json: obstacles[0].max: expected [x, y, z], got [1,1]",
                error(withObstacles("{ \"type\": \"box\", \"min\": [0, 0, 1], \"max\": [1, 1] }")));
        assertEquals("courses/x.json: obstacles[0].thickness: expected a number, got a string",
                error(withObstacles("{ \"type\": \"wall\", \"from\": [1, 1], \"to\": [2, 1], \"thickness\": \"NaN\", \"height\": 0.1 }")));
        assertEquals("courses/x.json: obstacles[0].colour: unknown field (known: type, position, radius, height, restitution, motion)",
                error(withObstacles("{ \"type\": \"tree\", \"position\": [2, 2], \"radius\": 0.2, \"height\": 2, \"colour\": 1 }")));
        assertEquals("courses/x.json: physics.ballRadius: must be > 0, got 0",
                error(edit("\"model\": \"classic\" }", "\"model\": \"classic\", \"ballRadius\": 0 }")));
        assertEquals("courses/x.json: physics.groundRestitution: must be between 0 and 1, got -0.1",
                error(edit("\"model\": \"classic\" }", "\"model\": \"classic\", \"groundRestitution\": -0.1 }")));
    }

    /** {@code physics.puttsOnly} (classic tracks): read, written back only when set, refused when not a boolean. */
    @Test
    void puttsOnlyIsReadWrittenAndChecked() throws CourseException {
        Course plain = CourseLoader.parse(edit("\"model\": \"classic\" }", "\"model\": \"classic\" }"), SRC);
        assertFalse(plain.physics().puttsOnly());
        assertFalse(CourseWriter.toJson(plain).contains("puttsOnly"));
        Course putts = CourseLoader.parse(edit("\"model\": \"classic\" }", "\"model\": \"classic\", \"puttsOnly\": true }"), SRC);
        assertTrue(putts.physics().puttsOnly());
        assertEquals(putts.physics(), CourseLoader.parse(CourseWriter.toJson(putts), SRC).physics());
        assertTrue(putts.physics().withModel(PhysicsModel.COMPLETE).withFlight(0, 0.5).puttsOnly());
        assertEquals("courses/x.json: physics.puttsOnly: expected true or false, got \"yes\"",
                error(edit("\"model\": \"classic\" }", "\"model\": \"classic\", \"puttsOnly\": \"yes\" }")));
    }

    @Test
    void modelFilesResolveBesideTheCourseAndReportProblemsWithTheirLine(@TempDir Path dir) throws IOException, CourseException {
        Files.createDirectories(dir.resolve("models"));
        Files.writeString(dir.resolve("models/tetra.obj"), TETRA, StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("models/broken.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 7\n", StandardCharsets.UTF_8);
        String model = "{ \"type\": \"model\", \"file\": \"models/%s\", \"position\": [1, 2, 0.1], \"scale\": 0.5 }";
        Path course = dir.resolve("c.json");
        Files.writeString(course, withObstacles(String.format(model, "tetra.obj")), StandardCharsets.UTF_8);
        Obstacle.Model m = (Obstacle.Model) CourseLoader.load(course).obstacles().get(0);
        assertEquals("models/tetra.obj", m.file());
        assertEquals(4, m.mesh().triangleCount());
        assertEquals(0.5, m.scale());
        assertEquals(0, m.rotationDeg());

        Files.writeString(course, withObstacles(String.format(model, "broken.obj")), StandardCharsets.UTF_8);
        assertEquals(course + ": obstacles[0].file: models/broken.obj: line 3: vertex index 7 is out of range (2 defined so far)",
                assertThrowsCourse(course));
        Files.writeString(course, withObstacles(String.format(model, "missing.obj")), StandardCharsets.UTF_8);
        String missing = assertThrowsCourse(course);
        assertTrue(missing.startsWith(course + ": obstacles[0].file: no such file: models/missing.obj (looked in "), missing);
    }

    @Test
    void obstaclesAndFlightFieldsRoundTripThroughTheWriter(@TempDir Path dir) throws IOException, CourseException {
        Files.writeString(dir.resolve("tetra.obj"), TETRA, StandardCharsets.UTF_8);
        String json = withObstacles(String.join(", ",
                "{ \"type\": \"wall\", \"from\": [0, 0.1], \"to\": [1, 0], \"thickness\": 0.05, \"height\": 0.1, \"restitution\": 0.8 }",
                "{ \"type\": \"tree\", \"position\": [2, 2], \"radius\": 0.2, \"height\": 2 }",
                "{ \"type\": \"box\", \"min\": [0, 1, 0], \"max\": [1, 2, 0.5], \"rotationDeg\": -12.5 }",
                "{ \"type\": \"model\", \"file\": \"tetra.obj\", \"position\": [1, 2, 0.1], \"rotationDeg\": 90, \"scale\": 0.25 }"))
                .replace("\"model\": \"classic\" }", "\"model\": \"classic\", \"ballRadius\": 0.03, \"dragCoefficient\": 0, \"groundRestitution\": 0.4 }");
        Path file = dir.resolve("c.json");
        Files.writeString(file, json, StandardCharsets.UTF_8);
        Course c = CourseLoader.load(file);
        Path saved = dir.resolve("sub/saved.json");
        Files.createDirectories(saved.getParent());
        CourseWriter.save(c, saved); // the model file is not beside the copy: the course's own mesh is used for the check
        Files.writeString(dir.resolve("sub/tetra.obj"), TETRA, StandardCharsets.UTF_8);
        Course back = CourseLoader.load(saved);
        assertEquals(c, back);
        assertEquals(CourseWriter.toJson(c), CourseWriter.toJson(back));
        assertEquals(0.03, back.physics().ballRadius());
        assertEquals(0.4, back.physics().groundRestitution());
    }

    private static String assertThrowsCourse(Path course) {
        return org.junit.jupiter.api.Assertions.assertThrows(CourseException.class, () -> CourseLoader.load(course)).getMessage();
    }
}
