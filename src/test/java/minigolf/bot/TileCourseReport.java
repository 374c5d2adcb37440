package minigolf.bot;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Tool (test scope): the planner on generated tile courses against the exhaustive search. For
 * each course the planner plays (budget {@link #BUDGET}, at most 10 strokes, 60 s), then the exhaustive
 * search looks for a game at least one stroke shorter (so its cost stays bounded): the baseline
 * is what it finds, else the planner's own count (the search found nothing shorter, within
 * {@link #MAX_LEVELS} strokes).
 * Arguments: SEED COUNT [FIRST] [--no-search] (the planner only) [--bot=NAME] (another bot, e.g. planner-aces)
 * [--max-levels=N] (search at most N strokes deep, default {@link #MAX_LEVELS}) [--budget=N] (the bot's simulations per game)
 * [--fewer-than=RUNS_CSV] (no bot plays: each course's strokes are taken from an {@code experiment}'s runs.csv, its first
 * row for that course, and the search looks for a shorter game than those; for games that took minutes, as the
 * planner's full search on fresh courses).
 */
final class TileCourseReport {
    /** The search goes at most this many strokes deep (each level costs about a million simulations). */
    static final int MAX_LEVELS = 3;
    /**
     * The bot's simulation budget per game: large enough for planner-aces' two-stroke search
     * ({@code TwoStrokeSearch}, which leaves 20,000 to the later strokes); the time limit stays 60 s.
     */
    static final long BUDGET = 1_000_000;

    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        int first = args.length > 2 && !args[2].startsWith("--") ? Integer.parseInt(args[2]) : 0;
        boolean search = !List.of(args).contains("--no-search");
        String bot = List.of(args).stream().filter(a -> a.startsWith("--bot=")).map(a -> a.substring(6)).findFirst()
                .orElse("planner");
        int levels = List.of(args).stream().filter(a -> a.startsWith("--max-levels=")).map(a -> Integer.parseInt(a.substring(13)))
                .findFirst().orElse(MAX_LEVELS);
        long budget = List.of(args).stream().filter(a -> a.startsWith("--budget=")).map(a -> Long.parseLong(a.substring(9)))
                .findFirst().orElse(BUDGET);
        Map<String, String[]> played = List.of(args).stream().filter(a -> a.startsWith("--fewer-than=")).findFirst()
                .map(a -> runs(Path.of(a.substring(13)))).orElse(null);
        List<World> worlds = TileCourses.generate(seed, first + count);
        System.out.println("| course | planner holed | planner strokes | simulations | ms | fewer found by the search | search simulations | search s |");
        System.out.println("|---|---|---:|---:|---:|---|---:|---:|");
        for (int i = first; i < first + count; i++) {
            World w = worlds.get(i);
            boolean holed;
            int strokes;
            long simulations;
            double ms;
            if (played != null) {
                // A suite written by TileCourseFiles names its files tile-SEED-NN.
                String file = String.format(Locale.ROOT, "tile-%d-%02d", seed, i);
                String[] row = played.getOrDefault(w.course().name(), played.get(file));
                if (row == null) throw new IllegalArgumentException("no run of " + w.course().name() + " (" + file + ") in the runs file");
                holed = Boolean.parseBoolean(row[0]);
                strokes = Integer.parseInt(row[1]);
                simulations = Long.parseLong(row[2]);
                ms = Double.parseDouble(row[3]);
            } else {
                Playthrough.Result p = Playthrough.play(Bots.create(bot), w, SimulationSettings.DEFAULT, 10, budget, 1,
                        CancellationToken.withTimeLimit(60), BotProgress.NONE);
                holed = p.holed();
                strokes = p.strokes();
                simulations = p.simulations();
                ms = p.wallNanos() / 1e6;
            }
            int cap = search ? Math.min(holed ? strokes - 1 : 4, levels) : 0;
            ExhaustiveStrokeSearch.Result s = cap < 1 ? null : ExhaustiveStrokeSearch.search(w,
                    new ExhaustiveStrokeSearch.Grid(0.3, 180, 24, cap, 0.6, 5));
            String fewer = !search ? "not searched" : s == null ? "– (hole-in-one)"
                    : s.strokes() == 0 ? "none in ≤ " + cap : String.valueOf(s.strokes());
            System.out.printf(Locale.ROOT, "| %s | %s | %d | %d | %.0f | %s | %d | %.1f |%n", w.course().name(),
                    holed ? "yes" : "no", strokes, simulations, ms, fewer,
                    s == null ? 0 : s.simulations(), s == null ? 0 : s.seconds());
        }
    }

    /** An experiment's runs.csv: for each course its first row's {holed, strokes, simulations, wall ms}. */
    static Map<String, String[]> runs(Path csv) {
        try {
            List<String> lines = Files.readAllLines(csv);
            List<String> head = List.of(lines.get(0).split(","));
            int course = head.indexOf("course"), holed = head.indexOf("holed"), strokes = head.indexOf("strokes"),
                    sims = head.indexOf("simulations"), ms = head.indexOf("wall_ms");
            if (Math.min(Math.min(course, holed), Math.min(Math.min(strokes, sims), ms)) < 0) {
                throw new IllegalArgumentException(csv + ": not an experiment's runs.csv (header " + lines.get(0) + ")");
            }
            Map<String, String[]> out = new LinkedHashMap<>();
            for (String line : lines.subList(1, lines.size())) {
                String[] f = line.split(",");
                out.putIfAbsent(f[course], new String[] {f[holed], f[strokes], f[sims], f[ms]});
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
