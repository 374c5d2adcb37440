package minigolf.course;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.*;

class CourseWriterTest {

    static Course lake() throws CourseException {
        return CourseLoader.parse(CourseLoaderTest.BASE, "lake");
    }

    static Course roundTrip(Course c) throws CourseException {
        return CourseLoader.parse(CourseWriter.toJson(c), "round-trip");
    }

    @Test
    void writesTheSchemaInTheDocumentedOrder() throws CourseException {
        String json = CourseWriter.toJson(lake());
        String[] keys = {"\"format\": 1", "\"name\": \"Lake\"", "\"terrain\": { \"height\": \"0.4*(0.9-exp(-(x^2+y^2)/8))\" }",
                "\"bounds\": { \"min\": [-5, -5], \"max\": [5, 5] }",
                "\"physics\": { \"gravity\": 9.81, \"kineticFriction\": 0.08, \"staticFriction\": 0.2, \"maxSpeed\": 5, \"model\": \"classic\" }",
                "\"start\": [-3, 0]", "\"hole\": { \"position\": [4, 1], \"radius\": 0.15, \"rule\": \"rest\" }",
                "\"zones\": [", "{ \"shape\": { \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }, \"kineticFriction\": 0.25, \"staticFriction\": 0.3 }",
                "\"obstacles\": []"};
        int at = -1;
        for (String k : keys) {
            int next = json.indexOf(k);
            assertTrue(next > at, "expected " + k + " after position " + at + " in\n" + json);
            at = next;
        }
        assertTrue(json.startsWith("{\n") && json.endsWith("}\n"));
    }

    @Test
    void lakeRoundTripsExactly() throws CourseException {
        Course c = lake();
        assertEquals(c, roundTrip(c));
        assertEquals(CourseWriter.toJson(c), CourseWriter.toJson(roundTrip(c)));
    }

    @Test
    void awkwardDoublesRoundTripBitForBit() throws CourseException {
        double[] values = {0.1, 1.0 / 3, -0.0, Double.MIN_VALUE, 4.9e-320, 1e-300, 1e300, Double.MAX_VALUE / 4,
                123456789.123456789, 2e-7, Math.nextUp(1.0), Math.PI, 1e21, 9007199254740993.0};
        for (double v : values) {
            Vec2 p = new Vec2(v == 0 ? v : Math.signum(v) * 1e-3 * Math.min(Math.abs(v), 1), 0);
            Course c = lake();
            Course big = new Course(1, "n", c.terrain(), new Bounds(-Double.MAX_VALUE / 2, -5, Double.MAX_VALUE / 2, 5),
                    new PhysicsSettings(v > 0 ? v : 9.81, Math.abs(v), Math.abs(v), v > 0 ? v : 5, PhysicsModel.COMPLETE),
                    p, new Hole(new Vec2(v, 1), v > 0 ? v : 0.1, HoleRule.CAPTURE, v > 0 ? v : null),
                    List.of(new Zone(new Shape.Circle(new Vec2(v, -v), v > 0 ? v : 1), Math.abs(v), Math.abs(v))));
            Course back = roundTrip(big);
            assertEquals(big, back, "value " + v);
            assertEquals(Double.doubleToRawLongBits(v), Double.doubleToRawLongBits(back.hole().position().x()), "bits of " + v);
        }
    }

    @Test
    void randomCoursesRoundTripExactly() throws CourseException {
        Random rnd = new Random(20240601L);
        for (int n = 0; n < 300; n++) {
            Course c = randomCourse(rnd);
            Course back = roundTrip(c);
            assertEquals(c, back, "random course " + n);
        }
    }

    static Course randomCourse(Random rnd) {
        double x0 = rnd.nextDouble() * 20 - 10, y0 = rnd.nextDouble() * 20 - 10;
        double w = 0.5 + rnd.nextDouble() * 30, d = 0.5 + rnd.nextDouble() * 30;
        Bounds b = new Bounds(x0, y0, x0 + w, y0 + d);
        TerrainSpec terrain;
        if (rnd.nextBoolean()) {
            String[] exprs = {"0.1", "0.05*x + 0.02*y + 1", "0.4*(0.9-exp(-(x^2+y^2)/8))", "sin(x)*cos(y) + 2",
                    "max(0, 1 - sqrt(x^2 + y^2)) + atan2(y, x)", "-x^2 + pi*e"};
            terrain = new TerrainSpec.HeightExpression(exprs[rnd.nextInt(exprs.length)]);
        } else {
            int rows = 2 + rnd.nextInt(6), cols = 2 + rnd.nextInt(6);
            boolean friction = rnd.nextBoolean();
            double[][] h = new double[rows][cols], k = friction ? new double[rows][cols] : null,
                    s = rnd.nextBoolean() ? new double[rows][cols] : null;
            for (int j = 0; j < rows; j++) {
                for (int i = 0; i < cols; i++) {
                    h[j][i] = rnd.nextGaussian();
                    if (k != null) k[j][i] = rnd.nextDouble();
                    if (s != null) s[j][i] = rnd.nextDouble() * 2;
                }
            }
            terrain = new TerrainSpec.HeightGrid(new Vec2(rnd.nextGaussian() * 5, rnd.nextGaussian() * 5),
                    0.01 + rnd.nextDouble(), h, k, s);
        }
        PhysicsSettings physics = new PhysicsSettings(1 + rnd.nextDouble() * 20, rnd.nextDouble(), rnd.nextDouble(),
                0.1 + rnd.nextDouble() * 10, rnd.nextBoolean() ? PhysicsModel.CLASSIC : PhysicsModel.COMPLETE);
        Vec2 start = new Vec2(x0 + rnd.nextDouble() * w, y0 + rnd.nextDouble() * d);
        Hole hole = new Hole(new Vec2(x0 + rnd.nextDouble() * w, y0 + rnd.nextDouble() * d), 1e-3 + rnd.nextDouble() * 0.3,
                rnd.nextBoolean() ? HoleRule.REST : HoleRule.CAPTURE, rnd.nextBoolean() ? null : 0.01 + rnd.nextDouble() * 3);
        List<Zone> zones = new ArrayList<>();
        for (int z = rnd.nextInt(4); z > 0; z--) {
            Vec2 p = new Vec2(rnd.nextGaussian() * 5, rnd.nextGaussian() * 5);
            Shape shape = switch (rnd.nextInt(3)) {
                case 0 -> new Shape.Rect(p, new Vec2(p.x() + 1e-6 + rnd.nextDouble(), p.y() + 1e-6 + rnd.nextDouble()));
                case 1 -> new Shape.Circle(p, 1e-6 + rnd.nextDouble() * 3);
                default -> {
                    List<Vec2> pts = new ArrayList<>();
                    for (int i = 3 + rnd.nextInt(5); i > 0; i--) pts.add(new Vec2(rnd.nextGaussian(), rnd.nextGaussian()));
                    yield new Shape.Polygon(pts);
                }
            };
            zones.add(new Zone(shape, rnd.nextDouble(), rnd.nextDouble()));
        }
        String name = "Course " + rnd.nextInt(1000) + (rnd.nextBoolean() ? " \"quoted\" \\ é ✓ \t tab" : "");
        return new Course(1, name, terrain, b, physics, start, hole, zones);
    }

    @Test
    void nonFiniteNumbersAreNotWritten() throws CourseException {
        Course c = lake().withPhysics(new PhysicsSettings(Double.NaN, 0.1, 0.2, 5, PhysicsModel.CLASSIC));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CourseWriter.toJson(c));
        assertEquals("physics.gravity: not a finite number: NaN", e.getMessage());
    }

    // ---- atomic save ----

    static List<String> listing(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void saveWritesAFileThatLoadsBackEqual(@TempDir Path dir) throws IOException, CourseException {
        Path f = dir.resolve("lake.json");
        CourseWriter.save(lake(), f);
        assertEquals(lake(), CourseLoader.load(f));
        assertEquals(CourseWriter.toJson(lake()), Files.readString(f));
        assertEquals(List.of("lake.json"), listing(dir), "no temp files left");
    }

    @Test
    void saveReplacesAnExistingFileAndKeepsItsPermissions(@TempDir Path dir) throws IOException, CourseException {
        Path f = dir.resolve("c.json");
        Files.writeString(f, "old");
        boolean posix = dir.getFileSystem().supportedFileAttributeViews().contains("posix");
        if (posix) Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r-----"));
        Course other = lake().withPhysics(new PhysicsSettings(9.81, 0.1, 0.3, 4, PhysicsModel.COMPLETE));
        CourseWriter.save(other, f);
        assertEquals(other, CourseLoader.load(f));
        if (posix) assertEquals("rw-r-----", PosixFilePermissions.toString(Files.getPosixFilePermissions(f)));
        assertEquals(List.of("c.json"), listing(dir));
    }

    @Test
    void failedMoveLeavesTheTargetAloneAndRemovesTheTempFile(@TempDir Path dir) throws IOException {
        // The target is a non-empty directory: the temp file is written, then the rename fails.
        Path target = dir.resolve("busy.json");
        Files.createDirectory(target);
        Files.writeString(target.resolve("keep.txt"), "keep");
        CourseException e = assertThrows(CourseException.class, () -> CourseWriter.save(lake(), target));
        // the reason after the last colon is the operating system's ("Is a directory" on Linux)
        assertTrue(e.getMessage().startsWith(target + ": cannot save: cannot replace the file: "), e.getMessage());
        assertEquals(List.of("busy.json"), listing(dir), "no temp files left");
        assertEquals("keep", Files.readString(target.resolve("keep.txt")));
    }

    @Test
    void failingPathLeavesTheOldFileIntact(@TempDir Path dir) throws IOException {
        Path old = dir.resolve("old.json");
        Files.writeString(old, "previous contents");
        Path impossible = old.resolve("sub.json"); // the parent is a regular file
        CourseException e = assertThrows(CourseException.class, () -> CourseWriter.save(lake(), impossible));
        assertTrue(e.getMessage().startsWith(impossible + ": cannot save: cannot create a temporary file in " + old + ": "),
                e.getMessage());
        assertEquals("previous contents", Files.readString(old));
        assertEquals(List.of("old.json"), listing(dir));
    }

    @Test
    void invalidCourseIsNotSavedOverTheOldFile(@TempDir Path dir) throws IOException, CourseException {
        Path f = dir.resolve("c.json");
        Files.writeString(f, "previous contents");
        Course bad = new Course(1, "Bad", lake().terrain(), lake().bounds(), lake().physics(), lake().start(),
                new Hole(new Vec2(4, 1), -0.1, HoleRule.REST, null), List.of());
        CourseException e = assertThrows(CourseException.class, () -> CourseWriter.save(bad, f));
        assertEquals(f + ": cannot save: hole.radius: must be > 0, got -0.1", e.getMessage());
        Course nan = lake().withPhysics(new PhysicsSettings(9.81, Double.POSITIVE_INFINITY, 0.2, 5, PhysicsModel.CLASSIC));
        CourseException e2 = assertThrows(CourseException.class, () -> CourseWriter.save(nan, f));
        assertEquals(f + ": cannot save: physics.kineticFriction: not a finite number: Infinity", e2.getMessage());
        assertEquals("previous contents", Files.readString(f, StandardCharsets.UTF_8));
        assertEquals(List.of("c.json"), listing(dir));
    }
}
