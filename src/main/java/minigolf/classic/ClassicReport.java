package minigolf.classic;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import minigolf.bot.experiment.RunRecord;
import minigolf.course.CourseException;
import minigolf.physics.World;

/**
 * The classic tracks' figures (docs/classic-tracks.md): how many files were imported and load, and
 * how bots played the imported tracks in an {@code experiment} compared with the human scores in
 * the index.
 */
public final class ClassicReport {
    /** The most strokes a game counts as "holed within" for the planner's target. */
    public static final int STROKE_TARGET = 30;
    /** How close a bot's mean strokes must come to the human mean (a share of it). */
    public static final double AVERAGE_TOLERANCE = 0.25;

    private ClassicReport() {
    }

    /** The import: tracks in the index, files that failed (with why), courses that did not load (with why). */
    public record Import(List<ClassicIndex.Entry> tracks, List<String> failed, List<String> notLoaded) {
        public int files() {
            return tracks.size() + failed.size();
        }
    }

    /** One bot's figures over its runs on the indexed tracks. */
    public record BotFigures(String bot, int runs, int tracks, int holedWithin, int atMostBest, int withHumanBest,
                             double meanStrokes, double humanMean, double slowestSeconds) {
        public double ratio() {
            return meanStrokes / humanMean;
        }
    }

    /** Reads an import's index and (if {@code load}) loads every course as the game does. */
    public static Import readImport(Path imported, boolean load) throws IOException {
        ClassicIndex.Index index = ClassicIndex.read(imported);
        List<String> notLoaded = new ArrayList<>();
        if (load) {
            for (ClassicIndex.Entry t : index.tracks()) {
                try {
                    World.load(t.course());
                } catch (CourseException | RuntimeException e) {
                    notLoaded.add(e.getMessage());
                }
            }
        }
        return new Import(index.tracks(), index.failed(), List.copyOf(notLoaded));
    }

    /** Reads an experiment's runs: its results.csv, else its runs.csv (a run still going). */
    public static List<RunRecord> readRuns(Path experiment) throws IOException {
        Path results = experiment.resolve("results.csv");
        boolean runsLog = !Files.isRegularFile(results);
        Path file = runsLog ? experiment.resolve("runs.csv") : results;
        List<RunRecord> runs = new ArrayList<>();
        List<String> lines = Files.readAllLines(file);
        for (int i = 1; i < lines.size(); i++) {
            String row = lines.get(i);
            if (row.isBlank()) continue;
            if (runsLog) row = row.substring(row.indexOf(',') + 1); // runs.csv starts with the run number
            try {
                runs.add(RunRecord.parse(row));
            } catch (IllegalArgumentException e) {
                throw new IOException(file + ": line " + (i + 1) + ": " + e.getMessage());
            }
        }
        return runs;
    }

    /** Each bot's figures over the runs on tracks of the index (runs on other courses are left out). */
    public static List<BotFigures> figures(Import imp, List<RunRecord> runs) {
        Map<String, ClassicIndex.Entry> byFolder = new LinkedHashMap<>();
        for (ClassicIndex.Entry t : imp.tracks()) byFolder.put(t.folder(), t);
        Map<String, List<RunRecord>> byBot = new LinkedHashMap<>();
        for (RunRecord r : runs) {
            if (byFolder.containsKey(r.course())) byBot.computeIfAbsent(r.bot(), k -> new ArrayList<>()).add(r);
        }
        List<BotFigures> out = new ArrayList<>();
        for (Map.Entry<String, List<RunRecord>> e : byBot.entrySet()) {
            int holedWithin = 0, atMostBest = 0, withBest = 0, withAverage = 0;
            double strokes = 0, human = 0, slowest = 0;
            java.util.Set<String> tracks = new java.util.HashSet<>();
            for (RunRecord r : e.getValue()) {
                ClassicIndex.Entry t = byFolder.get(r.course());
                tracks.add(t.folder());
                if (r.holed() && r.strokes() <= STROKE_TARGET) holedWithin++;
                if (t.bestStrokes() > 0) {
                    withBest++;
                    if (r.holed() && r.strokes() <= t.bestStrokes()) atMostBest++;
                }
                if (!Double.isNaN(t.averageStrokes())) {
                    withAverage++;
                    strokes += r.strokes();
                    human += t.averageStrokes();
                }
                slowest = Math.max(slowest, r.wallMs() / 1000);
            }
            out.add(new BotFigures(e.getKey(), e.getValue().size(), tracks.size(), holedWithin, atMostBest, withBest,
                    withAverage > 0 ? strokes / withAverage : Double.NaN, withAverage > 0 ? human / withAverage : Double.NaN,
                    slowest));
        }
        return out;
    }

    /** The report as Markdown. */
    public static String markdown(Import imp, List<BotFigures> bots) {
        StringBuilder sb = new StringBuilder();
        int loaded = imp.tracks().size() - imp.notLoaded().size();
        sb.append(String.format(Locale.ROOT, "Import: %d of %d tracks imported (%s; a file not imported counts as one track), %d of %d load%n",
                imp.tracks().size(), imp.files(), percent(imp.tracks().size(), imp.files()), loaded, imp.tracks().size()));
        for (String f : imp.failed()) sb.append("- not imported: ").append(f).append('\n');
        for (String f : imp.notLoaded()) sb.append("- does not load: ").append(f).append('\n');
        if (bots.isEmpty()) return sb.toString();
        sb.append('\n');
        sb.append("| bot | tracks | games | holed within ").append(STROKE_TARGET)
                .append(" strokes | at most the best human score | mean strokes | human mean (same tracks) | bot / human | slowest game |\n");
        sb.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (BotFigures b : bots) {
            sb.append(String.format(Locale.ROOT, "| %s | %d | %d | %s | %s | %.2f | %.2f | %.2f | %.0f s |%n", b.bot(), b.tracks(),
                    b.runs(), percent(b.holedWithin(), b.runs()), percent(b.atMostBest(), b.withHumanBest()), b.meanStrokes(),
                    b.humanMean(), b.ratio(), b.slowestSeconds()));
        }
        sb.append("\nA game not holed counts the strokes it played (a lower bound on its score).\n");
        return sb.toString();
    }

    private static String percent(int part, int whole) {
        return whole == 0 ? "-" : String.format(Locale.ROOT, "%d/%d = %.1f%%", part, whole, 100.0 * part / whole);
    }
}
