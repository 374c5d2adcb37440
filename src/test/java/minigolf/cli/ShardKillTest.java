package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import minigolf.bot.experiment.RunLog;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A shard killed part-way (SIGKILL, in a separate JVM) and run again with the same command resumes
 * where it stopped, redoes a row that the kill cut in half, and merges to the single machine's result.
 */
class ShardKillTest {
    private static final int SEEDS = 15;

    private static List<String> experiment(Path suite, Path out, String... more) {
        List<String> args = new ArrayList<>(List.of("experiment", "--suite", suite.toString(), "--bots", "planner,newton",
                "--seeds", Integer.toString(SEEDS), "--out", out.toString()));
        args.addAll(List.of(more));
        return args;
    }

    @Test
    void aKilledShardRunAgainMergesToTheSingleMachineResult(@TempDir Path dir) throws Exception {
        Path suite = ExperimentShardsTest.suite(dir);
        Path shards = dir.resolve("shards");
        int total = 2 * 2 * SEEDS, shardRuns = total / 2;

        // Shard 1/2 in its own JVM, killed once a few rows are on disk.
        List<String> command = new ArrayList<>(List.of(ProcessHandle.current().info().command().orElse("java"),
                "-Xmx256m", "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), "minigolf.Main"));
        command.addAll(experiment(suite, shards, "--shard", "1/2", "--threads", "1"));
        Process process = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(dir.resolve("killed.log").toFile()).start();
        Path log = shards.resolve("shard-1-of-2").resolve(RunLog.FILE_NAME);
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (rows(log) < 5 && process.isAlive() && System.nanoTime() < deadline) Thread.sleep(2);
        assertTrue(process.isAlive(), "the shard ended before it could be killed: " + Files.readString(dir.resolve("killed.log")));
        process.destroyForcibly();
        assertTrue(process.waitFor(30, TimeUnit.SECONDS));
        int afterKill = rows(log);
        assertTrue(afterKill >= 5 && afterKill < shardRuns, afterKill + " rows after the kill");

        // Make the last row half-written, as a kill in the middle of the write leaves it.
        String text = Files.readString(log);
        if (text.endsWith("\n")) {
            int lastStart = text.lastIndexOf('\n', text.length() - 2) + 1;
            String lastRow = text.substring(lastStart);
            Files.writeString(log, text.substring(0, lastStart) + lastRow.substring(0, lastRow.length() / 2));
        }
        int completeRows = (int) Files.readString(log).chars().filter(c -> c == '\n').count() - 1;

        CliRun rerun = ExperimentShardsTest.run(experiment(suite, shards, "--shard", "1/2", "--threads", "2"));
        assertEquals(0, rerun.code(), rerun.err());
        assertTrue(rerun.err().contains(shardRuns + " runs, " + completeRows + " done before (a cut-off last row redone), "
                + (shardRuns - completeRows) + " to run"), rerun.err());
        assertTrue(Files.readString(log).endsWith("\n"));
        assertEquals(shardRuns, rows(log));

        assertEquals(0, ExperimentShardsTest.run(experiment(suite, shards, "--shard", "0/2", "--threads", "1")).code());
        CliRun merge = CliRun.of("experiment-merge", shards.toString(), "--out", dir.resolve("merged").toString());
        assertEquals(0, merge.code(), merge.err());
        CliRun single = ExperimentShardsTest.run(experiment(suite, dir.resolve("single"), "--threads", "2"));
        assertEquals(0, single.code(), single.err());
        assertEquals(1 + total, Files.readAllLines(dir.resolve("merged/results.csv")).size());
        ExperimentShardsTest.assertSameExperiment(dir.resolve("single"), dir.resolve("merged"));
    }

    /** Complete rows in the log (lines ending in a newline, less the header). */
    private static int rows(Path log) throws IOException {
        if (!Files.exists(log)) return 0;
        byte[] bytes = Files.readAllBytes(log);
        int lines = 0;
        for (byte b : bytes) if (b == '\n') lines++;
        return Math.max(0, lines - 1);
    }
}
