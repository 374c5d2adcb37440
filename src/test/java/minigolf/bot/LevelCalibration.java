package minigolf.bot;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import minigolf.bot.level.Level;
import minigolf.bot.level.LevelBot;
import minigolf.bot.noise.HumanError;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.course.CourseException;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Tool (test scope): the opponents' levels against the fewest strokes on generated tile courses,
 * the figures the calibration table reports (docs/bots.md, "Opponents with levels").
 *
 * <p>Arguments: SEED COUNT GAMES [--baseline=FILE] [--search] [--levels=easy,medium,...] [--threads=N].
 * The fewest strokes of each course: planner-aces' game (budget 1,000,000), and with {@code --search}
 * also {@link ExhaustiveStrokeSearch} for a game at least one stroke shorter (as
 * {@link TileCourseReport}); read from FILE when it exists (lines "INDEX FEWEST"), else computed and
 * written there (with any missing line filled in). Each level then plays every course GAMES times (game seeds 1..GAMES, budget
 * {@link #BUDGET} a game, at most {@link #MAX_STROKES} strokes): its mean strokes over the fewest
 * is the course's ratio; the report gives the ratios' median and quartiles over the courses, as the
 * human figure does over tracks.
 */
final class LevelCalibration {
    /** A game's stroke limit, as the game's and the command line's default. */
    static final int MAX_STROKES = 10;
    /** Simulations per game: the game's 20,000 a stroke over the stroke limit. */
    static final long BUDGET = 20_000L * MAX_STROKES;
    /** planner-aces' time limit for a course's fewest strokes, s. */
    static final int ACES_SECONDS = 900;

    /** One level's games on one course. */
    record CourseResult(int course, int fewest, int[] strokes, boolean allHoled) {
        double mean() {
            return Arrays.stream(strokes).average().orElse(Double.NaN);
        }

        double ratio() {
            return mean() / fewest;
        }
    }

    /** A level's results over a set of courses. */
    record LevelResult(String level, List<CourseResult> courses) {
        double[] ratios() {
            return courses.stream().mapToDouble(CourseResult::ratio).sorted().toArray();
        }

        double median() {
            return quantile(ratios(), 0.5);
        }

        int holed() {
            return (int) courses.stream().filter(CourseResult::allHoled).count();
        }

        int maxStrokes() {
            return courses.stream().flatMapToInt(c -> Arrays.stream(c.strokes())).max().orElse(0);
        }
    }

    /** The q-quantile of sorted values (linear between neighbours). */
    static double quantile(double[] sorted, double q) {
        double pos = q * (sorted.length - 1);
        int lo = (int) Math.floor(pos), hi = (int) Math.ceil(pos);
        return sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
    }

    /** The fewest strokes for one course: planner-aces' game, shortened by the exhaustive search when asked. */
    static int fewest(World world, boolean search) {
        // Bounded by its simulations; the time limit only stops a runaway (at 60 s a loaded machine cut
        // three of seed 1001's courses short: no game holed within 10 strokes).
        java.lang.management.ThreadMXBean cpu = java.lang.management.ManagementFactory.getThreadMXBean();
        long cpuStart = cpu.getCurrentThreadCpuTime();
        Playthrough.Result aces = Playthrough.play(Bots.create("planner-aces"), world, SimulationSettings.DEFAULT, MAX_STROKES,
                1_000_000, 1, CancellationToken.withTimeLimit(ACES_SECONDS), BotProgress.NONE);
        // What the full search costs (the game sizes planner-aces' budget a stroke by it: BotCatalog).
        System.err.printf(Locale.ROOT, "planner-aces %s: %d strokes, %d simulations (most in one stroke %d), %.2f s CPU%n",
                world.course().name(), aces.strokes(), aces.simulations(),
                aces.shots().stream().mapToLong(Playthrough.PlayedShot::simulations).max().orElse(0),
                (cpu.getCurrentThreadCpuTime() - cpuStart) / 1e9);
        int best = aces.holed() ? aces.strokes() : MAX_STROKES;
        if (!search || best <= 1) return best;
        ExhaustiveStrokeSearch.Result s = ExhaustiveStrokeSearch.search(world,
                new ExhaustiveStrokeSearch.Grid(0.3, 180, 24, Math.min(best - 1, TileCourseReport.MAX_LEVELS), 0.6, 5));
        return s.strokes() > 0 ? s.strokes() : best;
    }

    /** A level's games on the courses (game seeds 1..games), on {@code threads} threads; the same results for any count. */
    static LevelResult play(String level, List<World> worlds, int[] fewest, int games, int threads) {
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<Integer>> runs = new ArrayList<>();
            for (World w : worlds) {
                for (int g = 1; g <= games; g++) {
                    long seed = g;
                    runs.add(pool.submit(() -> {
                        Playthrough.Result r = Playthrough.play(bot(level), w, SimulationSettings.DEFAULT, MAX_STROKES,
                                BUDGET, seed, CancellationToken.withTimeLimit(120), BotProgress.NONE);
                        return r.holed() ? r.strokes() : -r.strokes();
                    }));
                }
            }
            List<CourseResult> courses = new ArrayList<>();
            for (int c = 0; c < worlds.size(); c++) {
                int[] strokes = new int[games];
                boolean holed = true;
                for (int g = 0; g < games; g++) {
                    int s = runs.get(c * games + g).get();
                    holed &= s > 0;
                    strokes[g] = Math.abs(s);
                }
                courses.add(new CourseResult(c, fewest[c], strokes, holed));
            }
            return new LevelResult(level, courses);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        } finally {
            pool.shutdownNow();
        }
    }

    /** A level's total strokes over a round's holes, one total per game seed 1..games (every hole played by Playthrough). */
    static int[] roundTotals(String level, List<World> holes, int games, int threads) {
        return Arrays.stream(roundStrokes(level, holes, games, threads)).mapToInt(g -> Arrays.stream(g).sum()).toArray();
    }

    /** The seed of hole {@code hole} (0-based) in round game {@code game}. */
    static long holeSeed(int game, int hole) {
        return game * 1000L + hole;
    }

    /** A level's strokes on each of a round's holes, one row per game seed 1..games, on {@code threads} threads. */
    static int[][] roundStrokes(String level, List<World> holes, int games, int threads) {
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<Integer>> runs = new ArrayList<>();
            for (int g = 1; g <= games; g++) {
                for (int h = 0; h < holes.size(); h++) {
                    // A seed of its own for each hole: with the game's seed on every hole, a level's first
                    // stroke would be misplayed alike on all eighteen (all aces or none).
                    long seed = holeSeed(g, h);
                    World hole = holes.get(h);
                    runs.add(pool.submit(() -> Playthrough.play(bot(level), hole, SimulationSettings.DEFAULT, MAX_STROKES,
                            BUDGET, seed, CancellationToken.withTimeLimit(120), BotProgress.NONE).strokes()));
                }
            }
            int[][] strokes = new int[games][holes.size()];
            for (int g = 0; g < games; g++) {
                for (int h = 0; h < holes.size(); h++) strokes[g][h] = runs.get(g * holes.size() + h).get();
            }
            return strokes;
        } catch (Exception e) {
            throw new IllegalStateException(e);
        } finally {
            pool.shutdownNow();
        }
    }

    public static void main(String[] args) throws IOException {
        String roundFile = option(args, "--round=", null);
        if (roundFile != null) {
            mainRound(roundFile, args);
            return;
        }
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        int games = Integer.parseInt(args[2]);
        String baseline = option(args, "--baseline=", null);
        boolean search = List.of(args).contains("--search");
        List<String> levels = List.of(option(args, "--levels=", String.join(",", Level.ids())).split(","));
        int threads = Integer.parseInt(option(args, "--threads=", "1"));
        List<World> worlds = TileCourses.generate(seed, count);
        int[] fewest = new int[count];
        Path file = baseline == null ? null : Path.of(baseline);
        if (file != null && Files.exists(file)) {
            for (String line : Files.readAllLines(file)) {
                String[] p = line.trim().split("\\s+");
                if (p.length == 2 && Integer.parseInt(p[0]) < count) fewest[Integer.parseInt(p[0])] = Integer.parseInt(p[1]);
            }
        }
        StringBuilder written = new StringBuilder();
        boolean computed = false;
        for (int i = 0; i < count; i++) {
            if (fewest[i] == 0) {
                fewest[i] = fewest(worlds.get(i), search);
                computed = true;
            }
            written.append(i).append(' ').append(fewest[i]).append('\n');
        }
        if (file != null && computed) Files.writeString(file, written);
        System.out.println("fewest strokes (" + (search ? "planner-aces and the exhaustive search" : "planner-aces") + "): "
                + Arrays.toString(fewest));
        System.out.printf(Locale.ROOT, "tile seed %d, %d courses, %d games each, game seeds 1-%d, budget %,d a game, at most %d strokes%n",
                seed, count, games, games, BUDGET, MAX_STROKES);
        System.out.println("| level | median ratio | quartiles | holed (courses, all games) | max strokes | mean strokes |");
        System.out.println("|---|---:|---|---:|---:|---:|");
        for (String level : levels) {
            long started = System.nanoTime();
            LevelResult r = play(level, worlds, fewest, games, threads);
            double[] ratios = r.ratios();
            double mean = r.courses().stream().mapToDouble(CourseResult::mean).average().orElse(Double.NaN);
            System.out.printf(Locale.ROOT, "| %s | %.2f | %.2f-%.2f | %d/%d | %d | %.2f |  (%.0f s)%n", level, r.median(),
                    quantile(ratios, 0.25), quantile(ratios, 0.75), r.holed(), count, r.maxStrokes(), mean,
                    (System.nanoTime() - started) / 1e9);
            if (List.of(args).contains("--per-course")) {
                for (CourseResult c : r.courses()) {
                    System.out.printf(Locale.ROOT, "    tile %d-%d fewest %d strokes %s ratio %.2f%n", seed, c.course(), c.fewest(),
                            Arrays.toString(c.strokes()), c.ratio());
                }
            }
        }
    }

    /** {@code --round=FILE GAMES [--levels=...] [--threads=N] [--per-hole]}: each level's round totals against the round's par. */
    private static void mainRound(String roundFile, String[] args) {
        int games = Integer.parseInt(args[1]);
        int threads = Integer.parseInt(option(args, "--threads=", "1"));
        Round round;
        try {
            round = RoundLoader.load(Path.of(roundFile));
        } catch (CourseException e) {
            throw new IllegalArgumentException(e.getMessage());
        }
        List<World> holes = round.holes().stream().map(Round.Hole::world).toList();
        int par = round.holes().stream().mapToInt(Round.Hole::par).sum();
        System.out.printf(Locale.ROOT, "%s, par %d, game seeds 1-%d%n", round.name(), par, games);
        for (String level : option(args, "--levels=", String.join(",", Level.ids())).split(",")) {
            int[][] strokes = roundStrokes(level, holes, games, threads);
            int[] totals = Arrays.stream(strokes).mapToInt(g -> Arrays.stream(g).sum()).toArray();
            long aces = Arrays.stream(strokes).flatMapToInt(Arrays::stream).filter(s -> s == 1).count();
            long above = Arrays.stream(totals).filter(t -> t > par).count(), below = Arrays.stream(totals).filter(t -> t < par).count();
            System.out.printf(Locale.ROOT, "%s: totals %s; above par %d, below par %d, level with par %d; %d aces in %d games%n",
                    level, Arrays.toString(totals), above, below, games - above - below, aces, games);
            if (List.of(args).contains("--per-hole")) {
                for (int[] game : strokes) System.out.println("    holes " + Arrays.toString(game));
            }
        }
    }

    /**
     * A level by name, or a candidate written NAME:ANGLE_DEGREES:PACE:robust|planner[:ACE_DEGREES:ACE_PACE][@FROM[r][/SHRINK]]
     * (for tuning; ACE_*: the error on an attempt at a hole in one, else the same; after @ the care
     * ({@link LevelBot.Care}): from which stroke, r to lay up then, the shrink per stroke, 0.5 unless given).
     */
    static Bot bot(String level) {
        // Optional care: NAME:...@FROM[r][/SHRINK] (r: lays up as the robust bot once careful; shrink 0.5 unless given)
        LevelBot.Care care = LevelBot.Care.HALVING_FROM_SIXTH;
        if (level.contains("@")) {
            String c = level.substring(level.indexOf('@') + 1);
            level = level.substring(0, level.indexOf('@'));
            boolean layUp = c.contains("r");
            String[] parts = c.replace("r", "").split("/");
            care = new LevelBot.Care(Integer.parseInt(parts[0]), parts.length > 1 ? Double.parseDouble(parts[1]) : 0.5, layUp);
        }
        String[] p = level.split(":");
        if (p.length == 1) return Bots.create(level);
        HumanError error = new HumanError(Math.toRadians(Double.parseDouble(p[1])), Double.parseDouble(p[2]));
        HumanError ace = p.length > 4 ? new HumanError(Math.toRadians(Double.parseDouble(p[4])), Double.parseDouble(p[5])) : error;
        return new LevelBot(p[0], error, ace, p[3].equals("robust"), care);
    }

    private static String option(String[] args, String prefix, String fallback) {
        return List.of(args).stream().filter(a -> a.startsWith(prefix)).map(a -> a.substring(prefix.length())).findFirst()
                .orElse(fallback);
    }

    private LevelCalibration() {
    }
}
