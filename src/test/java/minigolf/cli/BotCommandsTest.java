package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** solve and experiment as a user meets them. */
class BotCommandsTest {
    private static final Path BENCH = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench");

    private static CliRun run(String... args) {
        return CliRun.of(args);
    }

    private static List<String> fields(JsonNode node) {
        List<String> names = new ArrayList<>();
        node.fieldNames().forEachRemaining(names::add);
        return names;
    }

    @Test
    void solvePrintsTheGameAsJson() throws IOException {
        CliRun r = run("solve", BENCH.resolve("two-putt.json").toString(), "--bot", "planner", "--seed", "4");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertEquals(List.of("bot", "course", "holed", "strokes", "simulations", "wallMs", "timedOut", "shots", "noise",
                "hideFriction"), fields(json));
        assertEquals("planner", json.get("bot").asText());
        assertEquals("Two-putt (no hole-in-one)", json.get("course").asText());
        assertTrue(json.get("holed").asBoolean());
        assertEquals(2, json.get("strokes").asInt());
        JsonNode shots = json.get("shots");
        assertEquals(2, shots.size());
        assertEquals(List.of("velocity", "intended", "wait", "outcome", "end", "simulations"), fields(shots.get(0)));
        assertEquals(0.0, shots.get(0).get("wait").asDouble(), "nothing moves on this course: no wait");
        // Without noise the stroke is played as chosen.
        assertEquals(shots.get(0).get("intended"), shots.get(0).get("velocity"));
        assertEquals("stopped", shots.get(0).get("outcome").asText());
        assertEquals("holed", shots.get(1).get("outcome").asText());
        long sum = shots.get(0).get("simulations").asLong() + shots.get(1).get("simulations").asLong();
        assertEquals(json.get("simulations").asLong(), sum);
    }

    /** The game without its wall time: what must not depend on the thread count. */
    private static JsonNode withoutTime(CliRun r) throws IOException {
        assertEquals(0, r.code(), r.err());
        com.fasterxml.jackson.databind.node.ObjectNode json = (com.fasterxml.jackson.databind.node.ObjectNode) new ObjectMapper().readTree(r.out());
        json.remove("wallMs");
        return json;
    }

    @Test
    void solveSpreadsTheSweepsOverThreadsAndPlaysTheSameGame(@TempDir Path dir) throws IOException {
        // planner-aces sweeps all round (the dense sweep, the one-putt map's sweep) on this two-putt course.
        String course = BENCH.resolve("two-putt.json").toString();
        JsonNode one = withoutTime(run("solve", course, "--bot", "planner-aces", "--seed", "4"));
        JsonNode three = withoutTime(run("solve", course, "--bot", "planner-aces", "--seed", "4", "--threads", "3"));
        assertEquals(one, three);
        assertTrue(one.get("simulations").asLong() > 360, one.toString());
        CliRun zero = run("solve", course, "--threads", "0");
        assertEquals(2, zero.code());
        assertEquals("minigolf: --threads: must be 1 to 256, got 0", zero.err().trim());
        CliRun many = run("experiment", "--suite", BENCH.toString(), "--out", dir.toString(), "--sweep-threads", "257");
        assertEquals(2, many.code());
        assertEquals("minigolf: --sweep-threads: must be 1 to 256, got 257", many.err().trim());
    }

    @Test
    void solveWithoutASolutionInTheBudgetReportsNotHoled() throws IOException {
        CliRun r = run("solve", BENCH.resolve("lake-bowl.json").toString(), "--bot", "newton", "--budget", "3",
                "--max-strokes", "2");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertFalse(json.get("holed").asBoolean());
        assertTrue(json.get("simulations").asLong() <= 3);
    }

    @Test
    void aTimeLimitThatRunsOutEndsTheGameWithTheBestShotSoFar(@TempDir Path dir) throws IOException {
        // Over before the bot starts: the physics guess (into the pond on the line), then the game stops.
        CliRun r = run("solve", BENCH.resolve("pond.json").toString(), "--bot", "graph", "--time-limit", "1e-9");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertTrue(json.get("timedOut").asBoolean());
        assertFalse(json.get("holed").asBoolean());
        assertEquals(0, json.get("simulations").asLong());
        assertEquals(1, json.get("shots").size());
        assertEquals("water", json.get("shots").get(0).get("outcome").asText());
        CliRun zero = run("solve", BENCH.resolve("flat-7m.json").toString(), "--time-limit", "0");
        assertEquals(2, zero.code());
        assertEquals("minigolf: --time-limit: must be a number of seconds > 0 and at most 1000000, got 0.0", zero.err().trim());
        CliRun negative = run("experiment", "--suite", BENCH.toString(), "--out", dir.toString(), "--time-limit", "-1");
        assertEquals(2, negative.code());
        assertTrue(negative.err().startsWith("minigolf: --time-limit: must be"), negative.err());
    }

    @Test
    void badArgumentsGiveOneLineAndExitCodeTwo(@TempDir Path dir) throws IOException {
        CliRun unknown = run("solve", BENCH.resolve("flat-7m.json").toString(), "--bot", "oracle");
        assertEquals(2, unknown.code());
        assertEquals("minigolf: --bot: unknown bot 'oracle'; known: grid, local, newton, swarm, astar, astar-newton, "
                + "astar-swarm, graph, planner, planner-aces, robust, easy, medium, hard, pro", unknown.err().trim());
        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{\"format\": 1}");
        CliRun bad = run("solve", broken.toString());
        assertEquals(2, bad.code());
        assertTrue(bad.err().startsWith("minigolf: " + broken), bad.err());
        assertEquals(1, bad.err().trim().lines().count());
        CliRun noSuite = run("experiment", "--suite", dir.resolve("missing").toString(), "--out", dir.toString());
        assertEquals(2, noSuite.code());
        assertEquals("minigolf: --suite: " + dir.resolve("missing") + ": no such folder", noSuite.err().trim());
        CliRun badBots = run("experiment", "--suite", BENCH.toString(), "--bots", "planner,nope", "--out", dir.toString());
        assertEquals(2, badBots.code());
        assertTrue(badBots.err().startsWith("minigolf: --bots: unknown bot 'nope'"), badBots.err());
    }

    @Test
    void experimentWritesResultsSummaryAndCharts(@TempDir Path dir) throws IOException {
        Path suite = Files.createDirectories(dir.resolve("suite"));
        Files.copy(BENCH.resolve("flat-7m.json"), suite.resolve("flat-7m.json"));
        Files.copy(BENCH.resolve("two-putt.json"), suite.resolve("two-putt.json"));
        Path out = dir.resolve("out");
        CliRun r = run("experiment", "--suite", suite.toString(), "--bots", "planner,astar", "--seeds", "2",
                "--out", out.toString(), "--threads", "2");
        assertEquals(0, r.code(), r.err());
        List<String> csv = Files.readAllLines(out.resolve("results.csv"));
        assertEquals("course,bot,seed,noise_position,noise_velocity,holed,strokes,hole_in_one,simulations,wall_ms", csv.get(0));
        assertEquals(1 + 2 * 2 * 2, csv.size());
        assertTrue(csv.get(1).startsWith("flat-7m,planner,1,0.0,0.0,true,1,true,"), csv.get(1));
        String summary = Files.readString(out.resolve("summary.md"));
        String line = summary.lines().filter(l -> l.startsWith("| two-putt | planner |")).findFirst().orElseThrow();
        // Holed every time, never in one (it cannot be), in 2 strokes.
        assertTrue(line.startsWith("| two-putt | planner | 100% | 0% |") && line.endsWith("| 2 |"), line);
        for (String png : new String[] {"simulations.png", "success.png", "noise-holed.png", "noise-strokes.png"}) {
            byte[] bytes = Files.readAllBytes(out.resolve(png));
            assertTrue(bytes.length > 1000);
            assertEquals((byte) 0x89, bytes[0]);
            assertEquals('P', bytes[1]);
        }
        assertTrue(r.err().contains("8/8 runs"), r.err());
        // Each run's strokes, one JSON line each, with the wait before every shot (0: nothing moves here).
        List<String> shots = Files.readAllLines(out.resolve("shots.jsonl"));
        assertEquals(8, shots.size());
        com.fasterxml.jackson.databind.JsonNode first = new com.fasterxml.jackson.databind.ObjectMapper().readTree(shots.get(0));
        assertEquals(0.0, first.get("shots").get(0).get("wait").asDouble());
        assertTrue(first.get("shots").get(0).has("velocity") && first.has("seed") && first.has("course"));
    }

    @Test
    void solveReportsTheWaitWhereObstaclesMove() throws IOException {
        Path course = java.nio.file.Path.of(System.getProperty("minigolf.projectDir", "."), "src", "test", "resources",
                "elements", "sliding-gate.json");
        CliRun r = run("solve", course.toString(), "--bot", "planner", "--max-strokes", "3");
        assertEquals(0, r.code(), r.err());
        com.fasterxml.jackson.databind.JsonNode json = new com.fasterxml.jackson.databind.ObjectMapper().readTree(r.out());
        assertTrue(json.get("holed").asBoolean(), r.out());
        for (com.fasterxml.jackson.databind.JsonNode shot : json.get("shots")) {
            double wait = shot.get("wait").asDouble();
            assertTrue(wait >= 0 && wait < 4, "a wait within the gate's 4 s period: " + wait);
        }
    }

    @Test
    void theOpponentsByLevelPlayInSolveAndExperiment(@TempDir Path dir) throws IOException {
        CliRun solve = run("solve", BENCH.resolve("two-putt.json").toString(), "--bot", "hard", "--seed", "2");
        assertEquals(0, solve.code(), solve.err());
        JsonNode json = new ObjectMapper().readTree(solve.out());
        assertEquals("hard", json.get("bot").asText());
        assertTrue(json.get("holed").asBoolean());
        assertTrue(json.get("strokes").asInt() >= 2 && json.get("strokes").asInt() <= 10, solve.out());
        Path suite = Files.createDirectories(dir.resolve("suite"));
        Files.copy(BENCH.resolve("flat-7m.json"), suite.resolve("flat-7m.json"));
        Path out = dir.resolve("out");
        CliRun r = run("experiment", "--suite", suite.toString(), "--bots", "easy,pro,planner", "--seeds", "2",
                "--out", out.toString(), "--threads", "1");
        assertEquals(0, r.code(), r.err());
        List<String> csv = Files.readAllLines(out.resolve("results.csv"));
        assertEquals(1 + 3 * 2, csv.size());
        // pro is the planner: an ace on flat-7m; easy holes within the limit.
        assertTrue(csv.stream().anyMatch(l -> l.startsWith("flat-7m,pro,1,0.0,0.0,true,1,true,")), csv.toString());
        assertTrue(csv.stream().filter(l -> l.startsWith("flat-7m,easy,")).allMatch(l -> l.contains(",true,")), csv.toString());
    }
}
