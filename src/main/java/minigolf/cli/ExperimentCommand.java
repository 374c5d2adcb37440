package minigolf.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import minigolf.bot.Bots;
import minigolf.bot.experiment.Charts;
import minigolf.bot.experiment.Experiment;
import minigolf.bot.experiment.RunRecord;
import minigolf.bot.experiment.Summary;
import minigolf.io.AtomicFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "experiment", description = "Runs bots on every course of a suite and writes results.csv, summary.md and charts.")
final class ExperimentCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--suite", required = true, paramLabel = "DIR", description = "Folder of course files (*.json).")
    Path suite;

    @Option(names = "--bots", paramLabel = "a,b,c|all", description = "Bots to compare (default: ${DEFAULT-VALUE}).")
    String botList = "all";

    @Option(names = "--seeds", paramLabel = "N", description = "Runs per course and bot, seeds 1..N (default: ${DEFAULT-VALUE}).")
    int seeds = 5;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Folder for the results (created).")
    Path out;

    @Option(names = "--budget", paramLabel = "N", description = "Most simulations per game (default: ${DEFAULT-VALUE}).")
    long budget = 20_000;

    @Option(names = "--max-strokes", paramLabel = "K", description = "Most shots per game (default: ${DEFAULT-VALUE}).")
    int maxStrokes = 10;

    @Option(names = "--threads", paramLabel = "T", description = "Worker threads (default: one per core, here ${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Override
    public Integer call() throws InterruptedException {
        List<String> bots = parseBots(botList);
        if (seeds < 1) throw new UserError("--seeds: must be at least 1, got " + seeds);
        if (budget < 1) throw new UserError("--budget: must be at least 1, got " + budget);
        if (maxStrokes < 1) throw new UserError("--max-strokes: must be at least 1, got " + maxStrokes);
        if (threads < 1) throw new UserError("--threads: must be at least 1, got " + threads);
        List<Experiment.SuiteCourse> courses = loadSuite(suite);
        Experiment experiment = new Experiment(courses, bots, seeds, budget, maxStrokes, threads);
        PrintWriter err = spec.commandLine().getErr();
        ProgressBar bar = new ProgressBar(err, experiment.runCount());
        List<RunRecord> records = experiment.run(bar::update);
        bar.finish();
        List<Summary.Line> lines = Summary.lines(records);
        try {
            Files.createDirectories(out);
            StringBuilder csv = new StringBuilder(RunRecord.CSV_HEADER).append('\n');
            for (RunRecord r : records) csv.append(r.csvRow()).append('\n');
            AtomicFile.write(out.resolve("results.csv"), csv.toString().getBytes(StandardCharsets.UTF_8));
            AtomicFile.write(out.resolve("summary.md"),
                    Summary.markdown(lines, seeds, budget, maxStrokes).getBytes(StandardCharsets.UTF_8));
            Charts.write(lines, out);
        } catch (IOException e) {
            throw new UserError(out + ": cannot write the results: " + e.getMessage());
        }
        spec.commandLine().getOut().println(Summary.markdown(lines, seeds, budget, maxStrokes));
        return 0;
    }

    static List<String> parseBots(String text) {
        if (text.trim().equals("all")) return Bots.names();
        List<String> names = new ArrayList<>();
        for (String part : text.split(",")) {
            String name = part.trim();
            if (name.isEmpty()) continue;
            if (Bots.create(name) == null) {
                throw new UserError("--bots: unknown bot '" + name + "'; known: " + String.join(", ", Bots.names()) + ", all");
            }
            if (!names.contains(name)) names.add(name);
        }
        if (names.isEmpty()) throw new UserError("--bots: no bot named");
        return names;
    }

    static List<Experiment.SuiteCourse> loadSuite(Path dir) {
        if (!Files.isDirectory(dir)) throw new UserError("--suite: " + dir + ": no such folder");
        List<Path> files;
        try (Stream<Path> listing = Files.list(dir)) {
            files = listing.filter(p -> p.getFileName().toString().endsWith(".json")).sorted().toList();
        } catch (IOException e) {
            throw new UserError("--suite: " + dir + ": cannot list: " + e.getMessage());
        }
        if (files.isEmpty()) throw new UserError("--suite: " + dir + ": no course files (*.json)");
        List<Experiment.SuiteCourse> courses = new ArrayList<>();
        for (Path f : files) {
            String name = f.getFileName().toString();
            courses.add(new Experiment.SuiteCourse(name.substring(0, name.length() - 5), CourseArgument.load(f)));
        }
        return courses;
    }

    /** A one-line bar on stderr, redrawn at most ten times a second. */
    private static final class ProgressBar {
        private final PrintWriter err;
        private final int total;
        private final long started = System.nanoTime();
        private long lastDrawn;

        ProgressBar(PrintWriter err, int total) {
            this.err = err;
            this.total = total;
        }

        synchronized void update(int done) {
            long now = System.nanoTime();
            if (done < total && now - lastDrawn < 100_000_000L) return;
            lastDrawn = now;
            int width = 30, filled = (int) ((long) width * done / total);
            err.print(String.format(Locale.ROOT, "\r[%s%s] %d/%d runs  %.1f s", "#".repeat(filled),
                    " ".repeat(width - filled), done, total, (now - started) / 1e9));
            err.flush();
        }

        void finish() {
            err.println();
            err.flush();
        }
    }
}
