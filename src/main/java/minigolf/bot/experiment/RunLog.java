package minigolf.bot.experiment;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;

/**
 * runs.csv, a shard's rows in the order its runs finished: "run,course,bot,...", one line per run,
 * appended and handed to the operating system as each run ends, so a killed job loses only the
 * runs in flight. Every line ends with a newline written in the same call as the line; a last
 * line without one was cut off by a kill and does not count (opening the log for writing cuts it
 * away, so its run is done again).
 */
public final class RunLog implements Closeable {
    public static final String FILE_NAME = "runs.csv";
    public static final String HEADER = "run," + RunRecord.CSV_HEADER;
    /** Between forced writes to the disk (a kill needs none; a crash of the machine loses at most this). */
    private static final long FORCE_INTERVAL_NANOS = 10_000_000_000L;

    /** One row: the run's index and its result. */
    public record Row(int run, RunRecord record) {
    }

    /** A log as read: its complete rows, and the bytes of a cut-off last line (0 when none). */
    public record Contents(List<Row> rows, long validLength, int partialBytes) {
        public BitSet done() {
            BitSet done = new BitSet();
            for (Row r : rows) done.set(r.run());
            return done;
        }
    }

    private final Path file;
    private final FileChannel channel;
    private final FileLock lock;
    private long lastForced = System.nanoTime();

    private RunLog(Path file, FileChannel channel, FileLock lock) {
        this.file = file;
        this.channel = channel;
        this.lock = lock;
    }

    /**
     * Reads the rows of a log and checks each against the plan and the shard (null: any run).
     *
     * @throws ExperimentException naming the file and line of a row that is not a valid row of
     *                             this plan, or of a run that appears twice
     */
    public static Contents read(Path file, RunPlan plan, Shard shard) throws IOException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            return new Contents(List.of(), 0, 0);
        }
        int end = bytes.length;
        while (end > 0 && bytes[end - 1] != '\n') end--;
        String text = new String(bytes, 0, end, StandardCharsets.UTF_8);
        List<Row> rows = new ArrayList<>();
        BitSet seen = new BitSet();
        int lineNumber = 0;
        for (String line : text.split("\n", -1)) {
            lineNumber++;
            if (lineNumber == 1 && end > 0) {
                if (!line.equals(HEADER)) throw new ExperimentException(file + ": line 1: expected the header '" + HEADER + "'");
                continue;
            }
            if (line.isEmpty()) continue;
            Row row = parseRow(file, lineNumber, line, plan, shard);
            if (seen.get(row.run())) throw new ExperimentException(file + ": line " + lineNumber + ": run " + row.run() + " appears twice");
            seen.set(row.run());
            rows.add(row);
        }
        return new Contents(rows, end, bytes.length - end);
    }

    private static Row parseRow(Path file, int lineNumber, String line, RunPlan plan, Shard shard) {
        int comma = line.indexOf(',');
        try {
            if (comma < 0) throw new IllegalArgumentException("no fields");
            int run = Integer.parseInt(line.substring(0, comma));
            if (run < 0 || run >= plan.size()) throw new IllegalArgumentException("run " + run + " is not in 0.." + (plan.size() - 1));
            if (shard != null && !shard.contains(run)) throw new IllegalArgumentException("run " + run + " is not in shard " + shard);
            RunRecord record = RunRecord.parse(line.substring(comma + 1));
            if (!plan.matches(run, record)) {
                RunPlan.Run expected = plan.run(run);
                throw new IllegalArgumentException("run " + run + " is " + expected.course() + ", " + expected.bot()
                        + ", seed " + expected.seed() + " in this experiment");
            }
            return new Row(run, record);
        } catch (IllegalArgumentException e) {
            throw new ExperimentException(file + ": line " + lineNumber + ": not a row of this experiment: " + e.getMessage());
        }
    }

    /**
     * Opens a log for appending, locked against a second process on the same shard, after
     * cutting away a partly written last line; {@code contents} must be what {@link #read} gave.
     */
    public static RunLog openForAppend(Path file, Contents contents) throws IOException {
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.WRITE, StandardOpenOption.READ);
        FileLock lock;
        try {
            lock = channel.tryLock();
            if (lock == null) throw new OverlappingFileLockException();
        } catch (OverlappingFileLockException e) {
            channel.close();
            throw new ExperimentException(file + ": another process is writing this shard (the file is locked); "
                    + "two jobs must not run the same shard at once");
        } catch (IOException e) {
            lock = null; // a file system without locks (some network mounts): go on unlocked
        }
        RunLog log = new RunLog(file, channel, lock);
        if (channel.size() != contents.validLength() + contents.partialBytes()) {
            log.close();
            throw new ExperimentException(file + ": changed while it was being read");
        }
        channel.truncate(contents.validLength());
        channel.position(contents.validLength());
        if (contents.validLength() == 0) log.write(HEADER + "\n");
        return log;
    }

    /** Appends one run's row; safe to call from several threads. */
    public synchronized void append(int run, RunRecord record) throws IOException {
        write(run + "," + record.csvRow() + "\n");
        long now = System.nanoTime();
        if (now - lastForced > FORCE_INTERVAL_NANOS) {
            channel.force(false);
            lastForced = now;
        }
    }

    private void write(String line) throws IOException {
        ByteBuffer buffer = ByteBuffer.wrap(line.getBytes(StandardCharsets.UTF_8));
        while (buffer.hasRemaining()) channel.write(buffer);
    }

    public Path file() {
        return file;
    }

    @Override
    public synchronized void close() throws IOException {
        if (!channel.isOpen()) return;
        try {
            channel.force(false);
            if (lock != null) lock.release();
        } finally {
            channel.close();
        }
    }
}
