package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The command line as a user meets it: JSON on stdout, one-line errors and exit code 2. */
class CommandLineTest {
    private static final Path COURSES = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses");

    private static CliRun run(String... args) {
        return CliRun.of(args);
    }

    private static String course(String name) {
        return COURSES.resolve(name).toString();
    }

    @Test
    void simulatePrintsTheFlatGroundClosedForm() throws IOException {
        // courses/flat.json: flat, the shot stops after v^2 / (2 mu_k g).
        CliRun r = run("simulate", course("flat.json"), "--velocity", "2,0");
        assertEquals(0, r.code(), r.err());
        JsonNode json = r.json();
        assertEquals("stopped", json.get("outcome").asText());
        double muK = new ObjectMapper().readTree(COURSES.resolve("flat.json").toFile())
                .get("physics").get("kineticFriction").asDouble();
        double startX = new ObjectMapper().readTree(COURSES.resolve("flat.json").toFile()).get("start").get(0).asDouble();
        assertEquals(startX + 4 / (2 * muK * 9.81), json.get("end").get(0).asDouble(), 1e-3);
        assertEquals(2 / (muK * 9.81), json.get("time").asDouble(), 1e-6);
        assertTrue(json.get("steps").asInt() > 0);
        assertEquals(List.of("outcome", "end", "time", "steps", "events"), fieldNames(json));
        assertEquals(0.1, json.get("end").get(2).asDouble(), 1e-12, "z: the ball rests on the ground, h = 0.1");
        assertEquals("stop", json.get("events").get(0).get("type").asText());
    }

    @Test
    void simulateOnTerrainThatIsNotFiniteOrFrictionThatOverflowsExitsTwoWithOneLine(@TempDir Path dir) throws IOException {
        String flat = java.nio.file.Files.readString(Path.of(course("flat.json")));
        Path nan = dir.resolve("nan.json"), huge = dir.resolve("huge.json"), fast = dir.resolve("fast.json");
        // Ground that changes faster than any step can follow: it ended "out" 4.5 m past the bounds with exit 0.
        java.nio.file.Files.writeString(fast, flat.replace("\"height\": \"0.1\"", "\"height\": \"0.2+0.01*sin(1e15*x)\""));
        java.nio.file.Files.writeString(nan, flat.replace("\"height\": \"0.1\"", "\"height\": \"sqrt(abs(x - 0.1) - 0.01) + 1\""));
        java.nio.file.Files.writeString(huge, flat.replaceAll("\"kineticFriction\": [0-9.]+", "\"kineticFriction\": 1e308")
                .replaceAll("\"staticFriction\": [0-9.]+", "\"staticFriction\": 1e308"));
        for (Path file : new Path[] {nan, huge, fast}) {
            // At 2 m/s the ball on the fast ground ended "out" at x = -8.5 (the bounds end at -4).
            CliRun r = run("simulate", file.toString(), "--velocity", file == fast ? "2,0" : "4,0");
            assertEquals(2, r.code(), r.out() + r.err());
            assertEquals("", r.out(), "no JSON with NaN or Infinity");
            assertEquals(1, r.err().strip().lines().count(), r.err());
            assertTrue(r.err().startsWith("minigolf: " + file + ": "), r.err());
        }
    }

    @Test
    void simulateOnTheLakeAimedAtTheCentreEndsInWater() throws IOException {
        CliRun r = run("simulate", course("lake.json"), "--velocity", "3,0");
        assertEquals(0, r.code(), r.err());
        JsonNode json = r.json();
        assertEquals("water", json.get("outcome").asText());
        double x = json.get("end").get(0).asDouble(), y = json.get("end").get(1).asDouble();
        // The lake's shore: 0.4 (0.9 - exp(-r^2/8)) = 0 at r = sqrt(-8 ln 0.9) = 0.9181 m.
        assertEquals(Math.sqrt(-8 * Math.log(0.9)), Math.hypot(x, y), 1e-6);
    }

    @Test
    void integratorModelAndTrajectoryOptionsWork(@TempDir Path dir) throws IOException {
        Path csv = dir.resolve("path.csv");
        CliRun r = run("simulate", course("sine-hills.json"), "--velocity", "1.5,-0.5", "--integrator", "euler",
                "--dt", "0.005", "--model", "complete", "--trajectory", csv.toString());
        assertEquals(0, r.code(), r.err());
        List<String> lines = Files.readAllLines(csv);
        assertEquals("t,x,y,vx,vy,z,vz", lines.get(0));
        assertEquals(r.json().get("steps").asInt() + 2, lines.size());
        String[] last = lines.get(lines.size() - 1).split(",");
        assertEquals(r.json().get("end").get(0).asDouble(), Double.parseDouble(last[1]), 1e-8);
    }

    @Test
    void badInputGivesOneLineAndExitCodeTwo(@TempDir Path dir) throws IOException {
        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{ \"format\": 1, ");
        String[][] cases = {
            {"simulate", course("lake.json"), "--velocity", "6,0"},
            {"simulate", course("lake.json"), "--velocity", "1"},
            {"simulate", course("lake.json"), "--velocity", "a,1"},
            {"simulate", course("lake.json"), "--velocity", "1,1", "--integrator", "verlet"},
            {"simulate", course("lake.json"), "--velocity", "1,1", "--model", "magic"},
            {"simulate", course("lake.json"), "--velocity", "1,1", "--dt", "-1"},
            {"simulate", course("lake.json"), "--velocity", "1,1", "--dt", "4.9e-324"}, // ran without end before
            {"simulate", course("lake.json"), "--velocity", "1,1", "--dt", "1e-9"}, // ran for minutes
            {"simulate", course("lake.json"), "--velocity", "1,1", "--dt", "0.05"},
            {"bench-accuracy", course("lake.json"), "--shots", "1", "--dt", "1e-9"},
            {"simulate", dir.resolve("missing.json").toString(), "--velocity", "1,1"},
            {"simulate", broken.toString(), "--velocity", "1,1"},
            {"simulate", course("lake.json")},
            {"bench-physics", course("lake.json"), "--shots", "0"},
            {"no-such-command"},
        };
        String[] expected = {
            "exceeds the course's maxSpeed of 5.0 m/s",
            "--velocity: expected 2 or 3 comma-separated numbers (VX,VY or VX,VY,VZ), got '1'",
            "--velocity: 'a' is not a number",
            "--integrator: expected rk4, rk2 or euler, got 'verlet'",
            "--model: expected classic or complete, got 'magic'",
            "--dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got -1.0",
            "--dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 4.9E-324",
            "--dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 1.0E-9",
            "--dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 0.05",
            "--dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 1.0E-9",
            "missing.json: cannot read: no such file",
            "broken.json: not valid JSON",
            "Missing required option: '--velocity=VX,VY[,VZ]'",
            "--shots: must be at least 1, got 0",
            "Unmatched argument at index 0: 'no-such-command'",
        };
        for (int i = 0; i < cases.length; i++) {
            CliRun r = run(cases[i]);
            assertEquals(2, r.code(), String.join(" ", cases[i]));
            assertTrue(r.err().contains(expected[i]), r.err());
            assertFalse(r.err().contains("\tat "), "no stack trace: " + r.err());
            assertEquals("", r.out());
        }
    }

    /** The command line takes every step the settings and saved games take, both ends included. */
    @Test
    void theStepRangeOfTheSettingsIsAccepted() {
        for (String dt : new String[]{"0.001", String.valueOf(1.0 / 30)}) {
            CliRun r = run("simulate", course("flat.json"), "--velocity", "1,0", "--dt", dt);
            assertEquals(0, r.code(), dt + ": " + r.err());
        }
    }

    @Test
    void benchPhysicsReportsShotsPerSecond() throws IOException {
        CliRun r = run("bench-physics", course("flat.json"), "--shots", "200");
        assertEquals(0, r.code(), r.err());
        assertEquals(200, r.json().get("shots").asInt());
        assertTrue(r.json().get("shotsPerSecond").asDouble() > 0);
        // Shared by three threads, each with its own simulator, the shots end exactly the same.
        CliRun three = run("bench-physics", course("lake.json"), "--shots", "300", "--threads", "3");
        CliRun one = run("bench-physics", course("lake.json"), "--shots", "300");
        assertEquals(0, three.code(), three.err());
        assertEquals(3, three.json().get("threads").asInt());
        assertEquals(one.json().get("checksum").asText(), three.json().get("checksum").asText());
        assertEquals(one.json().get("meanSteps").asDouble(), three.json().get("meanSteps").asDouble());
        assertTrue(three.json().get("bytesPerShot").asDouble() < 700, three.out());
        // CPU time never exceeds the wall time of the same thread.
        assertTrue(r.json().get("shotsPerCpuSecond").asDouble() >= 0.9 * r.json().get("shotsPerSecond").asDouble(), r.out());
    }

    @Test
    void benchAccuracyFindsRk4AtOneSixtiethWithinAMillimetre() throws IOException {
        CliRun r = run("bench-accuracy", course("sine-hills.json"), "--shots", "3");
        assertEquals(0, r.code(), r.err());
        assertEquals(3, r.json().get("withinOneMm").asInt(), r.out());
        assertTrue(r.json().get("maxErrorMm").asDouble() < 1, r.out());
    }

    /**
     * Shot 74 of `lake-obstacles` (seed 1) stops on the shore, or rolls into the lake a metre
     * away when its velocity changes by 1e-7 m/s: it is counted ill-conditioned and left out of
     * the errors, and the other covered shots are compared.
     */
    @Test
    void benchAccuracyCountsIllConditionedShotsApart() throws IOException {
        CliRun r = run("bench-accuracy", course("lake-obstacles.json"), "--shots", "75");
        assertEquals(0, r.code(), r.err());
        JsonNode json = r.json();
        assertEquals(1, json.get("illConditioned").asInt(), r.out());
        JsonNode shot = json.get("illConditionedShots").get(0);
        assertEquals(74, shot.get("shot").asInt(), r.out());
        assertTrue(shot.get("spreadMm").asDouble() > 1000, r.out());
        assertEquals(json.get("covered").asInt() - 1, json.get("compared").asInt(), r.out());
        assertEquals(json.get("compared").asInt(), json.get("withinOneMm").asInt(), r.out());
        assertTrue(json.get("maxErrorMm").asDouble() < 1, r.out());
    }

    private static List<String> fieldNames(JsonNode json) {
        List<String> names = new java.util.ArrayList<>();
        json.fieldNames().forEachRemaining(names::add);
        return names;
    }
}
