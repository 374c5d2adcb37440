package minigolf.bot.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** runs.csv: rows survive a kill, a cut-off last row is redone, anything else wrong is named. */
class RunLogTest {
    private static final RunPlan PLAN = new RunPlan(List.of("flat", "lake, \"big\""), List.of("planner", "swarm"), 3);

    private static RunRecord record(int run, long simulations) {
        RunPlan.Run r = PLAN.run(run);
        return new RunRecord(r.course(), r.bot(), r.seed(), run % 2 == 0, 1 + run % 3, run % 4 == 0, simulations, 12.5 + run);
    }

    @Test
    void rowsRoundTripThroughCsvEvenWithCommasAndQuotes() {
        RunRecord r = record(7, 1234);
        assertEquals("lake, \"big\"", r.course());
        assertEquals("\"lake, \"\"big\"\"\",planner,2,0.0,0.0,false,2,false,1234,19.500", r.csvRow());
        assertEquals(r, RunRecord.parse(r.csvRow()));
        assertEquals(r.csvRow(), RunRecord.parse(r.csvRow()).csvRow());
        assertEquals("expected 10 fields, found 7", assertThrows(IllegalArgumentException.class,
                () -> RunRecord.parse("flat,planner,1,true,1,true,1")).getMessage());
        RunRecord noisy = new RunRecord("flat", "robust", 3, 0.01, 0.05, true, 2, false, 99, 1.25);
        assertEquals("flat,robust,3,0.01,0.05,true,2,false,99,1.250", noisy.csvRow());
        assertEquals(noisy, RunRecord.parse(noisy.csvRow()));
    }

    @Test
    void aCutOffLastRowIsDroppedAndItsRunDoneAgain(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("runs.csv");
        Shard shard = new Shard(1, 2);
        RunLog.Contents empty = RunLog.read(file, PLAN, shard);
        try (RunLog log = RunLog.openForAppend(file, empty)) {
            for (int run : new int[] {1, 5, 3, 7}) log.append(run, record(run, 100 + run));
        }
        String full = Files.readString(file);
        assertEquals(RunLog.HEADER + "\n", full.substring(0, RunLog.HEADER.length() + 1));
        assertEquals(5, full.lines().count());
        // A kill in the middle of the last write: half of run 7's row is on disk.
        String cut = full.substring(0, full.length() - 9);
        Files.writeString(file, cut);
        RunLog.Contents contents = RunLog.read(file, PLAN, shard);
        assertEquals(List.of(1, 5, 3), contents.rows().stream().map(RunLog.Row::run).toList());
        assertEquals(record(5, 105), contents.rows().get(1).record());
        assertTrue(contents.partialBytes() > 0 && contents.partialBytes() < full.lines().toList().get(4).length());
        assertTrue(contents.done().get(3) && !contents.done().get(7));
        try (RunLog log = RunLog.openForAppend(file, contents)) {
            log.append(7, record(7, 107));
            log.append(9, record(9, 109));
        }
        RunLog.Contents again = RunLog.read(file, PLAN, shard);
        assertEquals(0, again.partialBytes());
        assertEquals(List.of(1, 5, 3, 7, 9), again.rows().stream().map(RunLog.Row::run).toList());
        assertEquals(full + "9," + record(9, 109).csvRow() + "\n", Files.readString(file));
    }

    @Test
    void aDamagedRowAWrongRunOrARepeatedRunIsNamed(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("runs.csv");
        String header = RunLog.HEADER + "\n";
        Files.writeString(file, header + "0," + record(0, 1).csvRow() + "\n2,flat,planner,3,tr\u0000\u0000\n"
                + "4," + record(4, 1).csvRow() + "\n");
        assertEquals(file + ": line 3: not a row of this experiment: expected 10 fields, found 4",
                assertThrows(ExperimentException.class, () -> RunLog.read(file, PLAN, null)).getMessage());
        Files.writeString(file, header + "1," + record(0, 1).csvRow() + "\n");
        assertEquals(file + ": line 2: not a row of this experiment: run 1 is flat, planner, seed 2 in this experiment",
                assertThrows(ExperimentException.class, () -> RunLog.read(file, PLAN, null)).getMessage());
        Files.writeString(file, header + "2," + record(2, 1).csvRow() + "\n");
        assertEquals(file + ": line 2: not a row of this experiment: run 2 is not in shard 1/2",
                assertThrows(ExperimentException.class, () -> RunLog.read(file, PLAN, new Shard(1, 2))).getMessage());
        Files.writeString(file, header + "2," + record(2, 1).csvRow() + "\n2," + record(2, 9).csvRow() + "\n");
        assertEquals(file + ": line 3: run 2 appears twice",
                assertThrows(ExperimentException.class, () -> RunLog.read(file, PLAN, null)).getMessage());
        Files.write(file, "course,bot\n".getBytes(StandardCharsets.UTF_8));
        assertTrue(assertThrows(ExperimentException.class, () -> RunLog.read(file, PLAN, null)).getMessage()
                .startsWith(file + ": line 1: expected the header"));
    }

    @Test
    void aSecondWriterOnTheSameShardIsRefused(@TempDir Path dir) throws IOException {
        Path file = dir.resolve("runs.csv");
        try (RunLog first = RunLog.openForAppend(file, RunLog.read(file, PLAN, null))) {
            first.append(0, record(0, 1));
            ExperimentException e = assertThrows(ExperimentException.class,
                    () -> RunLog.openForAppend(file, RunLog.read(file, PLAN, null)));
            assertTrue(e.getMessage().contains("another process is writing this shard"), e.getMessage());
        }
    }
}
