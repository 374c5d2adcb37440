package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** --noise-position, --noise-velocity and --hide-friction on solve and experiment. */
class NoiseCommandsTest {
    private static final Path BENCH = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench");

    @Test
    void solveReportsTheNoiseAndBothShots() throws IOException {
        String[] args = {"solve", BENCH.resolve("two-putt.json").toString(), "--seed", "3", "--noise-position", "0.01",
                "--noise-velocity", "0.05"};
        CliRun r = CliRun.of(args);
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertEquals(0.01, json.get("noise").get("position").asDouble());
        assertEquals(0.05, json.get("noise").get("velocity").asDouble());
        JsonNode first = json.get("shots").get(0);
        List<String> keys = new java.util.ArrayList<>();
        first.fieldNames().forEachRemaining(keys::add);
        assertEquals(List.of("velocity", "intended", "wait", "start", "outcome", "end", "simulations"), keys);
        double startX = first.get("start").get(0).asDouble();
        assertTrue(startX != json.get("shots").get(0).get("end").get(0).asDouble() && Math.abs(startX + 8) < 0.06,
                "the start strays by the position noise: " + startX);
        assertNotEquals(first.get("intended"), first.get("velocity"), "the played shot carries the noise");
        double dx = first.get("velocity").get(0).asDouble() - first.get("intended").get(0).asDouble();
        assertTrue(Math.abs(dx) < 0.05 * 6, "an error of six standard deviations: " + dx);
        assertEquals(withoutClock(r.out()), withoutClock(CliRun.of(args).out()), "same seed, same game");
    }

    private static String withoutClock(String json) {
        return json.replaceAll("\"wallMs\":[0-9.E-]+", "");
    }

    @Test
    void solveWithHiddenFrictionReportsTheEstimate() throws IOException {
        CliRun r = CliRun.of("solve", BENCH.resolve("two-putt.json").toString(), "--hide-friction");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertTrue(json.get("hideFriction").asBoolean());
        for (JsonNode shot : json.get("shots")) {
            assertTrue(shot.get("frictionEstimate").get("kineticFriction").asDouble() > 0, shot.toString());
        }
    }

    @Test
    void solveReportsAFrictionEstimateForEveryZone() throws IOException {
        Path course = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/friction/sand-band-fast.json");
        CliRun r = CliRun.of("solve", course.toString(), "--hide-friction");
        assertEquals(0, r.code(), r.err());
        JsonNode shots = new ObjectMapper().readTree(r.out()).get("shots");
        JsonNode last = shots.get(shots.size() - 1).get("frictionEstimate");
        // The course: green mu_k 0.06, a sand band (its one zone) mu_k 0.3; the prior is 0.1 for both.
        assertEquals(0.06, last.get("kineticFriction").asDouble(), 0.003, last.toString());
        assertEquals(1, last.get("zones").size());
        assertEquals(0.3, last.get("zones").get(0).get("kineticFriction").asDouble(), 0.015, last.toString());
    }

    @Test
    void badNoiseIsOneLineAndExitTwo(@TempDir Path dir) {
        for (String[] args : List.of(
                new String[]{"solve", BENCH.resolve("flat-7m.json").toString(), "--noise-velocity", "-1"},
                new String[]{"solve", BENCH.resolve("flat-7m.json").toString(), "--noise-position", "NaN"},
                new String[]{"experiment", "--suite", BENCH.toString(), "--out", dir.toString(), "--noise-velocity", "0,x"},
                new String[]{"experiment", "--suite", BENCH.toString(), "--out", dir.toString(), "--noise-position", "0,,1"})) {
            CliRun r = CliRun.of(args);
            assertEquals(2, r.code(), String.join(" ", args));
            assertEquals(1, r.err().trim().lines().count(), r.err());
            assertTrue(r.err().startsWith("minigolf: --noise-"), r.err());
        }
    }

    @Test
    void experimentRunsTheNoiseGrid(@TempDir Path dir) throws IOException {
        Path suite = Files.createDirectories(dir.resolve("suite"));
        Files.copy(BENCH.resolve("flat-7m.json"), suite.resolve("flat-7m.json"));
        Path out = dir.resolve("out");
        CliRun r = CliRun.of("experiment", "--suite", suite.toString(), "--bots", "planner,robust", "--seeds", "2",
                "--noise-position", "0,0.01", "--noise-velocity", "0,0.05", "--out", out.toString(), "--threads", "1");
        assertEquals(0, r.code(), r.err());
        List<String> csv = Files.readAllLines(out.resolve("results.csv"));
        // 1 course x (2 x 2 noise cells) x 2 bots x 2 seeds, position noise outer, then velocity, bot, seed.
        assertEquals(1 + 16, csv.size());
        assertTrue(csv.get(1).startsWith("flat-7m,planner,1,0.0,0.0,"), csv.get(1));
        assertTrue(csv.get(5).startsWith("flat-7m,planner,1,0.0,0.05,"), csv.get(5));
        assertTrue(csv.get(9).startsWith("flat-7m,planner,1,0.01,0.0,"), csv.get(9));
        assertTrue(csv.get(16).startsWith("flat-7m,robust,2,0.01,0.05,"), csv.get(16));
        String summary = Files.readString(out.resolve("summary.md"));
        assertTrue(summary.contains("| robust | 0.01 | 0.05 | 2 |"), summary);
        JsonNode manifest = new ObjectMapper().readTree(out.resolve("experiment.json").toFile());
        assertEquals(List.of(0.0, 0.01), List.of(manifest.get("options").get("noisePositions").get(0).asDouble(),
                manifest.get("options").get("noisePositions").get(1).asDouble()));
        for (String png : new String[]{"noise-holed.png", "noise-strokes.png"}) {
            assertTrue(Files.size(out.resolve(png)) > 1000, png);
        }
        // Another noise grid is another experiment: the folder refuses it.
        CliRun other = CliRun.of("experiment", "--suite", suite.toString(), "--bots", "planner,robust", "--seeds", "2",
                "--noise-velocity", "0,0.1", "--out", out.toString(), "--threads", "1");
        assertEquals(2, other.code());
        assertTrue(other.err().contains("--noise-velocity 0.0,0.05"), other.err());
    }
}
