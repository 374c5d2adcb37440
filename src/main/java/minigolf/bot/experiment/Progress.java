package minigolf.bot.experiment;

import java.io.Console;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.io.PrintWriter;
import java.lang.reflect.Method;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Shows how far an experiment is: on a terminal a bar redrawn at most ten times a second; in a
 * batch job (Slurm, Kubernetes: no terminal, output to a log file) one line a minute instead, so
 * the log stays readable and still shows the job is alive. Both give runs done, runs per second
 * and the time left; the rate counts only runs finished by this process (not those resumed).
 */
public final class Progress implements AutoCloseable {
    private final PrintWriter err;
    private final boolean terminal;
    private final int total;
    private final int resumed;
    private final long started = System.nanoTime();
    private final ScheduledExecutorService ticker;
    private int finished;
    private long lastDrawn;

    /**
     * @param total   the runs of this shard (or experiment)
     * @param resumed those already done before this process started
     * @param lineSeconds seconds between lines in batch mode
     */
    public Progress(PrintWriter err, boolean terminal, int total, int resumed, long lineSeconds) {
        this.err = err;
        this.terminal = terminal;
        this.total = total;
        this.resumed = resumed;
        if (terminal) {
            ticker = null;
        } else {
            ticker = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "experiment-progress");
                t.setDaemon(true);
                return t;
            });
            ticker.scheduleAtFixedRate(this::line, lineSeconds, lineSeconds, TimeUnit.SECONDS);
        }
    }

    /**
     * Whether standard error, where the progress goes, is a terminal. Java cannot ask that
     * directly: on Linux /proc names the file behind descriptor 2; elsewhere, whether standard
     * input and output are a terminal (on Java 22+ System.console() alone no longer says).
     */
    public static boolean onTerminal() {
        try {
            Path stderr = Path.of("/proc/self/fd/2");
            if (Files.exists(stderr, LinkOption.NOFOLLOW_LINKS)) {
                String target = Files.readSymbolicLink(stderr).toString();
                return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty");
            }
        } catch (IOException | RuntimeException e) {
            // fall through to the portable test
        }
        Console console = System.console();
        if (console == null) return false;
        try {
            Method isTerminal = Console.class.getMethod("isTerminal");
            return (Boolean) isTerminal.invoke(console);
        } catch (NoSuchMethodException e) {
            return true;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return false;
        }
    }

    /** One more run finished; called from the worker threads. */
    public synchronized void finished() {
        finished++;
        if (!terminal) return;
        long now = System.nanoTime();
        if (resumed + finished < total && now - lastDrawn < 100_000_000L) return;
        lastDrawn = now;
        int width = 30, filled = (int) ((long) width * (resumed + finished) / Math.max(1, total));
        err.print("\r[" + "#".repeat(filled) + " ".repeat(width - filled) + "] " + status() + "   ");
        err.flush();
    }

    private synchronized void line() {
        err.println("experiment: " + status());
        err.flush();
    }

    private String status() {
        double seconds = (System.nanoTime() - started) / 1e9;
        int done = resumed + finished;
        double rate = finished / Math.max(seconds, 1e-9);
        String left = finished == 0 ? "time left unknown" : "about " + duration((total - done) / rate) + " left";
        return String.format(Locale.ROOT, "%d/%d runs (%.0f%%), %.1f runs/s, %s", done, total,
                100.0 * done / Math.max(1, total), rate, left);
    }

    /** "42 s", "7 min", "3 h 20 min". */
    static String duration(double seconds) {
        if (seconds < 90) return Math.round(seconds) + " s";
        if (seconds < 5400) return Math.round(seconds / 60) + " min";
        long minutes = Math.round(seconds / 60);
        return minutes / 60 + " h " + minutes % 60 + " min";
    }

    /** Stops the ticker and prints the closing line. */
    @Override
    public synchronized void close() {
        if (ticker != null) ticker.shutdownNow();
        if (terminal) err.println();
        double seconds = (System.nanoTime() - started) / 1e9;
        err.println(String.format(Locale.ROOT, "experiment: %d/%d runs done (%d now, %d resumed) in %.1f s, %.1f runs/s",
                resumed + finished, total, finished, resumed, seconds, finished / Math.max(seconds, 1e-9)));
        err.flush();
    }
}
