package minigolf.course;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Function;

import static org.junit.jupiter.api.Assertions.*;

/** One test per kind of loader error: the exact one-line message, with the file name and the field path. */
class CourseLoaderTest {
    static final String SRC = "courses/x.json";

    /** A valid course using every section, each field on its own line so edits are easy to aim. */
    static final String BASE = String.join("\n",
            "{",
            "  \"format\": 1,",
            "  \"name\": \"Lake\",",
            "  \"terrain\": { \"height\": \"0.4*(0.9-exp(-(x^2+y^2)/8))\" },",
            "  \"bounds\": { \"min\": [-5, -5], \"max\": [5, 5] },",
            "  \"physics\": { \"gravity\": 9.81, \"kineticFriction\": 0.08, \"staticFriction\": 0.2, \"maxSpeed\": 5.0, \"model\": \"classic\" },",
            "  \"start\": [-3, 0],",
            "  \"hole\": { \"position\": [4, 1], \"radius\": 0.15, \"rule\": \"rest\" },",
            "  \"zones\": [ { \"shape\": { \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }, \"kineticFriction\": 0.25, \"staticFriction\": 0.3 } ],",
            "  \"obstacles\": []",
            "}");

    /** A valid grid course: 10 columns x 5 rows. */
    static String gridCourse(String heights, String extra) {
        return BASE.replace("\"terrain\": { \"height\": \"0.4*(0.9-exp(-(x^2+y^2)/8))\" }",
                "\"terrain\": { \"grid\": { \"origin\": [-5, -5], \"spacing\": 1, \"heights\": " + heights + extra + " } }");
    }

    static String rows(int rows, int cols, double value) {
        StringBuilder sb = new StringBuilder("[");
        for (int j = 0; j < rows; j++) {
            if (j > 0) sb.append(", ");
            sb.append('[');
            for (int i = 0; i < cols; i++) sb.append(i > 0 ? ", " : "").append(value);
            sb.append(']');
        }
        return sb.append(']').toString();
    }

    /** BASE with {@code from} (which must occur exactly once) replaced by {@code to}. */
    static String edit(String from, String to) {
        return edit(BASE, from, to);
    }

    static String edit(String json, String from, String to) {
        int at = json.indexOf(from);
        assertTrue(at >= 0 && json.indexOf(from, at + 1) < 0, "edit target must occur once: " + from);
        return json.replace(from, to);
    }

    static String error(String json) {
        return error(json, null);
    }

    static String error(String json, Function<TerrainSpec, HeightProbe> probes) {
        CourseException e = assertThrows(CourseException.class, () -> CourseLoader.parse(json, SRC, probes));
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        return e.getMessage();
    }

    // ---- the base course is fine ----

    @Test
    void baseCourseLoadsWithAllValues() throws CourseException {
        Course c = CourseLoader.parse(BASE, SRC);
        assertEquals(1, c.format());
        assertEquals("Lake", c.name());
        assertEquals(new TerrainSpec.HeightExpression("0.4*(0.9-exp(-(x^2+y^2)/8))"), c.terrain());
        assertEquals(new Bounds(-5, -5, 5, 5), c.bounds());
        assertEquals(new PhysicsSettings(9.81, 0.08, 0.2, 5.0, PhysicsModel.CLASSIC), c.physics());
        assertEquals(new Vec2(-3, 0), c.start());
        assertEquals(new Hole(new Vec2(4, 1), 0.15, HoleRule.REST, null), c.hole());
        assertEquals(List.of(new Zone(new Shape.Rect(new Vec2(1, -1), new Vec2(2, 1)), 0.25, 0.3)), c.zones());
    }

    @Test
    void defaultsApplyWhenOptionalFieldsAreAbsent() throws CourseException {
        String json = edit("\"gravity\": 9.81, ", "");
        json = edit(json, ", \"maxSpeed\": 5.0, \"model\": \"classic\"", "");
        json = edit(json, ", \"rule\": \"rest\"", "");
        json = edit(json, ",\n  \"obstacles\": []", "");
        json = json.replaceAll("\\n  \"zones\": .*\\n", "\n");
        json = edit(json, "\"hole\": { \"position\": [4, 1], \"radius\": 0.15 },", "\"hole\": { \"position\": [4, 1], \"radius\": 0.15 }");
        Course c = CourseLoader.parse(json, SRC);
        assertEquals(new PhysicsSettings(9.81, 0.08, 0.2, 5.0, PhysicsModel.CLASSIC), c.physics());
        assertEquals(HoleRule.REST, c.hole().rule());
        assertNull(c.hole().captureSpeed());
        assertEquals(List.of(), c.zones());
    }

    @Test
    void captureRuleAndCaptureSpeedAndCompleteModelAreRead() throws CourseException {
        String json = edit("\"rule\": \"rest\"", "\"rule\": \"capture\", \"captureSpeed\": 2.5");
        json = edit(json, "\"model\": \"classic\"", "\"model\": \"complete\"");
        Course c = CourseLoader.parse(json, SRC);
        assertEquals(new Hole(new Vec2(4, 1), 0.15, HoleRule.CAPTURE, 2.5), c.hole());
        assertEquals(PhysicsModel.COMPLETE, c.physics().model());
    }

    // ---- JSON syntax ----

    @Test
    void invalidJsonNamesLineAndColumnAndKeepsJacksonsFirstLine() {
        String json = "{ \"format\": 1,\n  \"name\": \"x\",\n  }";
        String m = error(json);
        assertTrue(m.startsWith("courses/x.json: not valid JSON at line 3, column 3: Unexpected character ('}'"), m);
        assertFalse(m.contains("Source"), "no source echo: " + m);
    }

    @Test
    void duplicateKeysAreAnError() {
        String m = error(edit("\"name\": \"Lake\",", "\"name\": \"Lake\", \"name\": \"Pond\","));
        assertTrue(m.startsWith("courses/x.json: not valid JSON at line 3, column "), m);
        assertTrue(m.endsWith(": duplicate field 'name'"), m);
    }

    @Test
    void nanAndInfinityLiteralsAreNotJson() {
        String m = error(edit("\"radius\": 0.15", "\"radius\": NaN"));
        assertTrue(m.startsWith("courses/x.json: not valid JSON at line 8, column "), m);
        String m2 = error(edit("\"radius\": 0.15", "\"radius\": Infinity"));
        assertTrue(m2.startsWith("courses/x.json: not valid JSON at line 8, column "), m2);
    }

    @Test
    void numbersTooLargeForADoubleAreNotFinite() {
        assertEquals("courses/x.json: hole.radius: must be a finite number, got Infinity",
                error(edit("\"radius\": 0.15", "\"radius\": 1e400")));
    }

    @Test
    void trailingContentIsAnError() {
        assertTrue(error(BASE + " {}").startsWith("courses/x.json: not valid JSON at line 11, column "));
    }

    @Test
    void emptyDocumentIsAnError() {
        assertEquals("courses/x.json: not valid JSON: the file holds only whitespace (3 characters), no content", error("  \n"));
    }

    @Test
    void topLevelMustBeAnObject() {
        assertEquals("courses/x.json: expected a JSON object at the top level, got an array", error("[1, 2]"));
    }

    // ---- structure ----

    @Test
    void missingRequiredField() {
        assertEquals("courses/x.json: physics.kineticFriction: missing required field",
                error(edit("\"kineticFriction\": 0.08, ", "")));
        assertEquals("courses/x.json: start: missing required field", error(edit("  \"start\": [-3, 0],\n", "")));
    }

    @Test
    void unknownFieldListsTheKnownOnes() {
        assertEquals("courses/x.json: physics.frction: unknown field (known: gravity, kineticFriction, staticFriction, maxSpeed, model, ballRadius, ballMass, dragCoefficient, airDensity, groundRestitution, puttsOnly)",
                error(edit("\"gravity\": 9.81,", "\"gravity\": 9.81, \"frction\": 0.1,")));
        assertEquals("courses/x.json: colour: unknown field (known: format, name, world, terrain, bounds, physics, start, hole, extraHoles, zones, obstacles, pushZones, magnets, teleports, bricks)",
                error(edit("\"name\": \"Lake\",", "\"name\": \"Lake\", \"colour\": \"green\",")));
    }

    @Test
    void wrongTypeOfValue() {
        assertEquals("courses/x.json: hole.radius: expected a number, got a string",
                error(edit("\"radius\": 0.15", "\"radius\": \"big\"")));
        assertEquals("courses/x.json: name: expected a string, got a number", error(edit("\"name\": \"Lake\"", "\"name\": 7")));
        assertEquals("courses/x.json: physics: expected an object, got null",
                error(BASE.replaceAll("\"physics\": \\{[^}]*}", "\"physics\": null")));
    }

    @Test
    void pointMustBeTwoNumbers() {
        assertEquals("courses/x.json: start: expected [x, y], got \"a\"", error(edit("\"start\": [-3, 0]", "\"start\": \"a\"")));
        assertEquals("courses/x.json: start: expected [x, y], got [1,2,3]", error(edit("\"start\": [-3, 0]", "\"start\": [1, 2, 3]")));
        assertEquals("courses/x.json: hole.position: expected [x, y], got [4,\"1\"]",
                error(edit("\"position\": [4, 1]", "\"position\": [4, \"1\"]")));
    }

    @Test
    void mustBePositive() {
        assertEquals("courses/x.json: hole.radius: must be > 0, got -0.1", error(edit("\"radius\": 0.15", "\"radius\": -0.1")));
        assertEquals("courses/x.json: physics.gravity: must be > 0, got 0", error(edit("\"gravity\": 9.81", "\"gravity\": 0")));
        assertEquals("courses/x.json: physics.maxSpeed: must be > 0, got -5", error(edit("\"maxSpeed\": 5.0", "\"maxSpeed\": -5")));
        assertEquals("courses/x.json: hole.captureSpeed: must be > 0, got 0",
                error(edit("\"rule\": \"rest\"", "\"rule\": \"capture\", \"captureSpeed\": 0.0")));
    }

    @Test
    void frictionMustNotBeNegative() {
        assertEquals("courses/x.json: physics.staticFriction: must be >= 0, got -0.2",
                error(edit("\"staticFriction\": 0.2", "\"staticFriction\": -0.2")));
        assertEquals("courses/x.json: zones[0].kineticFriction: must be >= 0, got -0.25",
                error(edit("\"kineticFriction\": 0.25", "\"kineticFriction\": -0.25")));
    }

    @Test
    void formatMustBeOne() {
        assertEquals("courses/x.json: format: unsupported format 2 (this engine reads format 1)",
                error(edit("\"format\": 1", "\"format\": 2")));
        assertEquals("courses/x.json: format: missing required field", error(edit("  \"format\": 1,\n", "")));
        assertEquals("courses/x.json: format: expected a number, got a string", error(edit("\"format\": 1", "\"format\": \"1\"")));
    }

    @Test
    void nameMustNotBeEmpty() {
        assertEquals("courses/x.json: name: must be a non-empty string", error(edit("\"name\": \"Lake\"", "\"name\": \"\"")));
    }

    /** A name is drawn on screen: 128 characters at most (a 100,000-character name once killed the game when drawn). */
    @Test
    void aNameHasAtMost128Characters() throws Exception {
        assertEquals("courses/x.json: name: too long: 100000 characters (the limit is 128)",
                error(edit("\"name\": \"Lake\"", "\"name\": \"" + "n".repeat(100_000) + "\"")));
        assertEquals(128, CourseLoader.parse(BASE.replace("\"name\": \"Lake\"", "\"name\": \"" + "n".repeat(128) + "\""),
                "courses/x.json").name().length());
    }

    /** A file that is not JSON at all (a system file a hostile file names): where, and nothing of its words. */
    @Test
    void aSyntaxErrorQuotesNoWordOfTheFile() {
        String m = assertThrows(CourseException.class, () -> CourseLoader.parse("root:x:0:0:root:/root:/bin/bash\n", "x.json")).getMessage();
        assertTrue(m.startsWith("x.json: not valid JSON at line 1, column 5: Unrecognized token"), m);
        assertFalse(m.contains("root"), m);
    }

    @Test
    void enumValues() {
        assertEquals("courses/x.json: zones[0].shape.type: expected one of rect, circle, polygon, cells, got \"star\"",
                error(edit("\"type\": \"rect\"", "\"type\": \"star\"")));
        assertEquals("courses/x.json: physics.model: expected one of classic, complete, got \"fast\"",
                error(edit("\"model\": \"classic\"", "\"model\": \"fast\"")));
        assertEquals("courses/x.json: hole.rule: expected one of rest, capture, got 3",
                error(edit("\"rule\": \"rest\"", "\"rule\": 3")));
    }

    @Test
    void boundsMinMustBeBelowMax() {
        assertEquals("courses/x.json: bounds: min must be < max in both axes, got min (-5, 5), max (5, 5)",
                error(edit("\"min\": [-5, -5]", "\"min\": [-5, 5]")));
    }

    @Test
    void zoneShapes() {
        assertEquals("courses/x.json: zones[0].shape: min must be < max in both axes, got min (3, -1), max (2, 1)",
                error(edit("\"min\": [1, -1]", "\"min\": [3, -1]")));
        String circle = edit("{ \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }",
                "{ \"type\": \"circle\", \"center\": [1, 1], \"radius\": 0 }");
        assertEquals("courses/x.json: zones[0].shape.radius: must be > 0, got 0", error(circle));
        String poly = edit("{ \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }",
                "{ \"type\": \"polygon\", \"points\": [[0, 0], [1, 0]] }");
        assertEquals("courses/x.json: zones[0].shape.points: a polygon needs at least 3 points, got 2", error(poly));
        String badPoint = edit("{ \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }",
                "{ \"type\": \"polygon\", \"points\": [[0, 0], [1, 0], [1]] }");
        assertEquals("courses/x.json: zones[0].shape.points[2]: expected [x, y], got [1]", error(badPoint));
        String unknown = edit("\"type\": \"rect\",", "\"type\": \"rect\", \"radius\": 1,");
        assertEquals("courses/x.json: zones[0].shape.radius: unknown field (known: type, min, max)", error(unknown));
    }

    @Test
    void anObstacleNeedsItsFields() {
        assertEquals("courses/x.json: obstacles[0].from: missing required field",
                error(edit("\"obstacles\": []", "\"obstacles\": [ { \"type\": \"wall\" } ]")));
    }

    // ---- terrain ----

    @Test
    void terrainNeedsExactlyOneOfHeightAndGrid() {
        assertEquals("courses/x.json: terrain: expected exactly one of height, grid, got neither",
                error(BASE.replaceAll("\"terrain\": \\{[^}]*}", "\"terrain\": {}")));
        assertEquals("courses/x.json: terrain: expected exactly one of height, grid, got both",
                error(gridCourse(rows(5, 10, 0.5), "").replace("\"terrain\": {", "\"terrain\": { \"height\": \"1\",")));
    }

    @Test
    void badExpressionNamesTheColumn() {
        assertEquals("courses/x.json: terrain.height: unknown function 'foo' at column 5"
                + " (allowed: sin, cos, tan, asin, acos, atan, atan2, exp, log, sqrt, abs, min, max, pow)",
                error(edit("\"0.4*(0.9-exp(-(x^2+y^2)/8))\"", "\"0.1+foo(x)\"")));
    }

    @Test
    void gridLoads() throws CourseException {
        String k = rows(5, 10, 0.1), s = rows(5, 10, 0.2);
        Course c = CourseLoader.parse(gridCourse(rows(5, 10, 0.5),
                ", \"kineticFriction\": " + k + ", \"staticFriction\": " + s), SRC);
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) c.terrain();
        assertEquals(10, g.columns());
        assertEquals(5, g.rows());
        assertEquals(new Vec2(-5, -5), g.origin());
        assertEquals(1.0, g.spacing());
        assertEquals(0.5, g.heights()[4][9]);
        assertEquals(0.1, g.kineticFriction()[2][3]);
        assertEquals(0.2, g.staticFriction()[0][0]);
    }

    @Test
    void gridRowsMustHaveEqualLength() {
        String h = rows(5, 10, 0.5).replaceFirst("(\\[0\\.5(, 0\\.5){9}]), (\\[0\\.5(, 0\\.5){9}]), (\\[0\\.5(, 0\\.5){9}]), \\[0\\.5, ",
                "$1, $3, $5, [");
        assertEquals("courses/x.json: terrain.grid.heights[3]: row has 9 values, expected 10", error(gridCourse(h, "")));
    }

    @Test
    void gridNeedsTwoByTwo() {
        assertEquals("courses/x.json: terrain.grid.heights: must have at least 2 rows of at least 2 values "
                        + "(bicubic interpolation needs a 2x2 grid), got 1 row of 10",
                error(gridCourse(rows(1, 10, 0.5), "")));
        assertEquals("courses/x.json: terrain.grid.heights: must have at least 2 rows of at least 2 values "
                        + "(bicubic interpolation needs a 2x2 grid), got 3 rows of 1",
                error(gridCourse(rows(3, 1, 0.5), "")));
    }

    @Test
    void gridSpacingMustBePositive() {
        assertEquals("courses/x.json: terrain.grid.spacing: must be > 0, got 0",
                error(gridCourse(rows(5, 10, 0.5), "").replace("\"spacing\": 1", "\"spacing\": 0")));
    }

    @Test
    void gridValuesMustBeNumbers() {
        String h = rows(5, 10, 0.5).replaceFirst("0\\.5]", "null]");
        assertEquals("courses/x.json: terrain.grid.heights[0][9]: expected a number, got null", error(gridCourse(h, "")));
    }

    @Test
    void frictionGridsHaveTheShapeOfHeightsAndNoNegativeValues() {
        assertEquals("courses/x.json: terrain.grid.kineticFriction: has 4 rows, expected 5 (the shape of heights)",
                error(gridCourse(rows(5, 10, 0.5), ", \"kineticFriction\": " + rows(4, 10, 0.1))));
        assertEquals("courses/x.json: terrain.grid.staticFriction[0]: row has 11 values, expected 10",
                error(gridCourse(rows(5, 10, 0.5), ", \"staticFriction\": " + rows(5, 11, 0.1))));
        assertEquals("courses/x.json: terrain.grid.kineticFriction[0][0]: must be >= 0, got -0.1",
                error(gridCourse(rows(5, 10, 0.5), ", \"kineticFriction\": " + rows(5, 10, -0.1))));
    }

    // ---- placement ----

    @Test
    void startAndHoleMustBeInsideTheBounds() {
        assertEquals("courses/x.json: start: (9, 0) is outside the bounds", error(edit("\"start\": [-3, 0]", "\"start\": [9, 0]")));
        assertEquals("courses/x.json: hole.position: (4, -5.5) is outside the bounds",
                error(edit("\"position\": [4, 1]", "\"position\": [4, -5.5]")));
    }

    @Test
    void startInWaterNeedsAProbe() throws CourseException {
        Function<TerrainSpec, HeightProbe> probes = spec -> (x, y) -> x < 0 ? -0.12 : 1.0;
        assertEquals("courses/x.json: start: (-3, 0) is in water (h = -0.12)", error(BASE, probes));
        // without a probe factory the water check is skipped
        assertEquals(new Vec2(-3, 0), CourseLoader.parse(BASE, SRC).start());
    }

    @Test
    void holeInWater() {
        Function<TerrainSpec, HeightProbe> probes = spec -> (x, y) -> x > 3 ? -0.0123456 : 0.0;
        assertEquals("courses/x.json: hole.position: (4, 1) is in water (h = -0.01235)", error(BASE, probes));
    }

    @Test
    void probeGetsTheCoursesTerrainAndDryLandPasses() throws CourseException {
        TerrainSpec[] seen = new TerrainSpec[1];
        Course c = CourseLoader.parse(BASE, SRC, spec -> {
            seen[0] = spec;
            return (x, y) -> 0.0; // h = 0 is not water
        });
        assertEquals(c.terrain(), seen[0]);
    }

    @Test
    void failingProbesBecomeCourseExceptions() {
        assertEquals("courses/x.json: terrain: cannot build the terrain: boom",
                error(BASE, spec -> { throw new IllegalStateException("boom"); }));
        assertEquals("courses/x.json: start: the terrain height at (-3, 0) is not a number", error(BASE, spec -> (x, y) -> Double.NaN));
        assertEquals("courses/x.json: start: cannot evaluate the terrain height at (-3, 0): bad",
                error(BASE, spec -> (x, y) -> { throw new ArithmeticException("bad"); }));
    }

    @Test
    void checkPlacementWorksOnAnyCourse() throws CourseException {
        Course c = CourseLoader.parse(BASE, SRC);
        CourseException e = assertThrows(CourseException.class,
                () -> CourseValidator.checkPlacement(c, (x, y) -> y > 0.5 ? -2.0 : 0.1, "mem"));
        assertEquals("mem: hole.position: (4, 1) is in water (h = -2)", e.getMessage());
        assertEquals("hole.position", e.path());
        CourseValidator.checkPlacement(c, (x, y) -> 0.1, "mem");
    }

    // ---- files ----

    @Test
    void missingFileCannotBeRead(@TempDir Path dir) {
        Path f = dir.resolve("nope.json");
        CourseException e = assertThrows(CourseException.class, () -> CourseLoader.load(f));
        assertEquals(f + ": cannot read: no such file", e.getMessage());
    }

    @Test
    void directoryCannotBeRead(@TempDir Path dir) {
        CourseException e = assertThrows(CourseException.class, () -> CourseLoader.load(dir));
        assertTrue(e.getMessage().startsWith(dir + ": cannot read: "), e.getMessage());
    }

    @Test
    void invalidUtf8CannotBeRead(@TempDir Path dir) throws IOException {
        Path f = dir.resolve("bad.json");
        Files.write(f, new byte[]{'{', (byte) 0xC3, (byte) 0x28, '}'});
        CourseException e = assertThrows(CourseException.class, () -> CourseLoader.load(f));
        assertEquals(f + ": cannot read: not UTF-8 text (an invalid byte sequence at byte 1): binary data or another encoding",
                e.getMessage());
    }

    @Test
    void loadUsesThePathAsTheSourceName(@TempDir Path dir) throws IOException, CourseException {
        Path f = dir.resolve("x.json");
        Files.writeString(f, "\uFEFF" + BASE, StandardCharsets.UTF_8); // a byte order mark is tolerated
        assertEquals("Lake", CourseLoader.load(f).name());
        Files.writeString(f, edit("\"radius\": 0.15", "\"radius\": -1"));
        CourseException e = assertThrows(CourseException.class, () -> CourseLoader.load(f, spec -> (x, y) -> 1.0));
        assertEquals(f + ": hole.radius: must be > 0, got -1", e.getMessage());
    }
}
