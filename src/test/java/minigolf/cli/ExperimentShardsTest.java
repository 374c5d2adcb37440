package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An experiment split into shards, run on different thread counts and merged, gives what one
 * machine's run gives: results.csv equal but for the wall-time column, summary.md equal but for
 * times, the charts and experiment.json byte for byte; and merge refuses what it cannot trust.
 */
class ExperimentShardsTest {
    static final Path BENCH = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench");

    static Path suite(Path dir) throws IOException {
        Path suite = Files.createDirectories(dir.resolve("suite"));
        Files.copy(BENCH.resolve("flat-7m.json"), suite.resolve("flat-7m.json"));
        Files.copy(BENCH.resolve("two-putt.json"), suite.resolve("two-putt.json"));
        return suite;
    }

    static List<String> experiment(Path suite, Path out, String... more) {
        List<String> args = new ArrayList<>(List.of("experiment", "--suite", suite.toString(), "--bots", "planner,astar,newton",
                "--seeds", "3", "--out", out.toString()));
        args.addAll(List.of(more));
        return args;
    }

    static CliRun run(List<String> args) {
        return CliRun.of(args.toArray(String[]::new));
    }

    /** results.csv without its last column (wall_ms): everything but what the clock measured. */
    static List<String> withoutWallTime(Path results) throws IOException {
        return Files.readAllLines(results).stream().map(l -> l.substring(0, l.lastIndexOf(','))).toList();
    }

    /** summary.md with the median-ms column blanked. */
    static String withoutTimes(Path summary) throws IOException {
        return Files.readAllLines(summary).stream().map(l -> {
            if (!l.startsWith("| ") || l.startsWith("| course")) return l;
            String[] cells = l.split("\\|", -1);
            cells[7] = " ms ";
            return String.join("|", cells);
        }).collect(Collectors.joining("\n"));
    }

    static void assertSameExperiment(Path single, Path merged) throws IOException {
        List<String> expected = withoutWallTime(single.resolve("results.csv"));
        assertEquals(expected, withoutWallTime(merged.resolve("results.csv")));
        assertEquals(withoutTimes(single.resolve("summary.md")), withoutTimes(merged.resolve("summary.md")));
        for (String f : new String[] {"simulations.png", "success.png", "noise-holed.png", "noise-strokes.png", "experiment.json"}) {
            assertArrayEquals(Files.readAllBytes(single.resolve(f)), Files.readAllBytes(merged.resolve(f)), f);
        }
    }

    @Test
    void shardsOnAnyThreadCountMergeToTheSingleMachineResult(@TempDir Path dir) throws IOException {
        Path suite = suite(dir);
        CliRun single = run(experiment(suite, dir.resolve("single"), "--threads", "2"));
        assertEquals(0, single.code(), single.err());
        List<String> rows = Files.readAllLines(dir.resolve("single/results.csv"));
        assertEquals(1 + 2 * 3 * 3, rows.size());
        // Run order: course, noise cell (one here), bot, seed.
        assertTrue(rows.get(1).startsWith("flat-7m,planner,1,0.0,0.0,true,1,true,1,"), rows.get(1));
        assertTrue(rows.get(18).startsWith("two-putt,newton,3,0.0,0.0,true,2,false,"), rows.get(18));

        Path shards = dir.resolve("shards");
        for (int k = 0; k < 3; k++) {
            CliRun shard = run(experiment(suite, shards, "--shard", k + "/3", "--threads", k == 1 ? "2" : "1"));
            assertEquals(0, shard.code(), shard.err());
            assertTrue(shard.out().startsWith("shard " + k + "/3 complete: 6 runs in "), shard.out());
            assertTrue(Files.exists(shards.resolve("shard-" + k + "-of-3/runs.csv")));
        }
        CliRun merge = CliRun.of("experiment-merge", shards.toString(), "--out", dir.resolve("merged").toString());
        assertEquals(0, merge.code(), merge.err());
        assertSameExperiment(dir.resolve("single"), dir.resolve("merged"));
        // The wall times did come from different runs: the comparison above is not of a file with itself.
        assertNotEquals(Files.readAllLines(dir.resolve("single/results.csv")), Files.readAllLines(dir.resolve("merged/results.csv")));

        // The shard folders may also be named one by one, in any order.
        CliRun byName = CliRun.of("experiment-merge", shards.resolve("shard-2-of-3").toString(),
                shards.resolve("shard-0-of-3").toString(), shards.resolve("shard-1-of-3").toString(),
                "--out", dir.resolve("merged2").toString());
        assertEquals(0, byName.code(), byName.err());
        assertEquals(Files.readAllLines(dir.resolve("merged/results.csv")), Files.readAllLines(dir.resolve("merged2/results.csv")));
    }

    @Test
    void mergeRefusesMissingDuplicatedOrForeignShards(@TempDir Path dir) throws IOException {
        Path suite = suite(dir);
        Path shards = dir.resolve("shards");
        for (int k = 0; k < 2; k++) assertEquals(0, run(experiment(suite, shards, "--shard", k + "/2", "--threads", "1")).code());
        String out = dir.resolve("merged").toString();

        CliRun missing = CliRun.of("experiment-merge", shards.resolve("shard-0-of-2").toString(), "--out", out);
        assertEquals(2, missing.code());
        assertTrue(missing.err().startsWith("minigolf: 9 of 18 runs are missing: shard(s) 1/2 not given; first missing: "
                + "run 1 (flat-7m, planner, seed 2), run 3 (flat-7m, astar, seed 1)"), missing.err());

        CliRun twice = CliRun.of("experiment-merge", shards.toString(), shards.resolve("shard-1-of-2").toString(), "--out", out);
        assertEquals(2, twice.code());
        assertTrue(twice.err().contains("shard-1-of-2: this shard folder is given twice"), twice.err());

        // A copy of a shard under another name duplicates its runs.
        Path copy = Files.createDirectories(dir.resolve("copy"));
        for (String f : new String[] {"experiment.json", "runs.csv"}) {
            Files.copy(shards.resolve("shard-1-of-2").resolve(f), copy.resolve(f));
        }
        CliRun duplicated = CliRun.of("experiment-merge", shards.toString(), copy.toString(), "--out", out);
        assertEquals(2, duplicated.code());
        assertTrue(duplicated.err().startsWith("minigolf: run 1 (flat-7m, planner, seed 2) is in both "), duplicated.err());

        // Same options but one course file changed: another experiment.
        Path otherSuite = Files.createDirectories(dir.resolve("other"));
        Files.copy(suite.resolve("flat-7m.json"), otherSuite.resolve("flat-7m.json"));
        Files.writeString(otherSuite.resolve("two-putt.json"), Files.readString(suite.resolve("two-putt.json")) + "\n");
        Path foreign = dir.resolve("foreign");
        assertEquals(0, run(experiment(otherSuite, foreign, "--shard", "1/2", "--threads", "1")).code());
        CliRun mixed = CliRun.of("experiment-merge", shards.resolve("shard-0-of-2").toString(),
                foreign.resolve("shard-1-of-2").toString(), "--out", out);
        assertEquals(2, mixed.code());
        assertTrue(mixed.err().contains("belongs to a different experiment than")
                && mixed.err().contains("different contents of course file(s) two-putt"), mixed.err());

        // Resuming into a folder of another experiment is refused too, naming the difference.
        List<String> moreSeeds = experiment(suite, shards, "--shard", "0/2");
        moreSeeds.set(moreSeeds.indexOf("3"), "4");
        CliRun resumeOther = run(moreSeeds);
        assertEquals(2, resumeOther.code());
        assertTrue(resumeOther.err().contains("holds runs of a different experiment (options --bots planner,astar,newton "
                + "--seeds 3 --budget 20000 --max-strokes 10 against --bots planner,astar,newton --seeds 4"), resumeOther.err());

        // One task of the 2-way split re-submitted alone would look like shard 0/1: refused.
        CliRun otherSplit = run(experiment(suite, shards, "--shard", "0/1"));
        assertEquals(2, otherSplit.code());
        assertTrue(otherSplit.err().startsWith("minigolf: " + shards + " already holds shards of a 2-way split "
                + "(shard-0-of-2), and this is shard 0/1. To re-run one task of that split give --shard K/2"), otherSplit.err());

        CliRun wholeIntoShards = run(experiment(suite, shards));
        assertEquals(2, wholeIntoShards.code());
        assertTrue(wholeIntoShards.err().startsWith("minigolf: " + shards + " holds shards (shard-0-of-2); a run without --shard "
                + "needs another --out"), wholeIntoShards.err());
        CliRun intoItself = CliRun.of("experiment-merge", shards.toString(), "--out", shards.toString());
        assertEquals(2, intoItself.code());
        assertEquals("minigolf: --out " + shards + ": is one of the folders being merged; give another folder",
                intoItself.err().trim());

        CliRun notShards = CliRun.of("experiment-merge", suite.toString(), "--out", out);
        assertEquals(2, notShards.code());
        assertTrue(notShards.err().contains("neither a shard folder"), notShards.err());
    }

    @Test
    void runningTheSameCommandAgainRunsNothingAndGivesTheSameResults(@TempDir Path dir) throws IOException {
        Path suite = suite(dir);
        Path out = dir.resolve("out");
        assertEquals(0, run(experiment(suite, out, "--threads", "2")).code());
        List<String> first = Files.readAllLines(out.resolve("results.csv"));
        CliRun again = run(experiment(suite, out, "--threads", "1"));
        assertEquals(0, again.code(), again.err());
        assertTrue(again.err().contains("18 runs, 18 done before, 0 to run"), again.err());
        assertEquals(first, Files.readAllLines(out.resolve("results.csv")));
    }
}
