package minigolf.game;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.play.Bots;
import minigolf.bot.CancellationToken;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.bot.NoiseModel;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * Checks a round's pars against opponents (docs/worlds.md, "Par"): each opponent plays every hole
 * over seeds 1..N with the game's rules, and a hole passes when the medium opponent's mean strokes
 * are at most par + 1.5, the pro's mean at most par, and the pro aces on at most a third of the
 * seeds (unless the hole is meant as an ace hole). A sweep of first strokes from the tee also gives
 * each hole's share of strokes that hole in one (how open its ace is). Plain Java; deterministic
 * for given opponents and seeds.
 */
public final class ParCheck {
    /** The medium opponent's mean may exceed par by at most this. */
    public static final double MEDIUM_ALLOWANCE = 1.5;
    /** The pro may ace on at most this share of the seeds of a hole not meant as an ace hole. */
    public static final double PRO_ACE_SHARE = 1.0 / 3;
    /** The game's opponents by level (minigolf.bot.level.Level): they carry their own human-like error. */
    public static final String PRO = "pro", MEDIUM = "medium";

    /**
     * An opponent: a bot of {@link Bots} (a level such as {@code medium} or {@code pro}, or an
     * algorithm) and extra noise its strokes are played with, under a label. {@code spec} reads
     * {@code BOT} or {@code BOT@SIGMA} (σ of the played velocity per component, m/s).
     */
    public record Opponent(String label, String bot, double velocityNoise) {
        public static Opponent parse(String label, String spec) {
            String[] p = spec.split("@", 2);
            String bot = p[0].trim();
            if (!Bots.allNames().contains(bot)) {
                throw new IllegalArgumentException(label + ": no bot '" + bot + "' (known: " + String.join(", ", Bots.allNames()) + ")");
            }
            double sigma = 0;
            if (p.length == 2) {
                try {
                    sigma = Double.parseDouble(p[1].trim());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(label + ": the noise after @ must be a number (m/s), got '" + p[1] + "'");
                }
                if (!(sigma >= 0 && sigma <= NoiseModel.MAX_SIGMA)) {
                    throw new IllegalArgumentException(label + ": the noise must be 0 to " + NoiseModel.MAX_SIGMA + " m/s, got " + p[1]);
                }
            }
            return new Opponent(label, bot, sigma);
        }

        @Override
        public String toString() {
            return bot + (velocityNoise > 0 ? "@" + velocityNoise : "");
        }
    }

    /** One opponent's games on one hole: strokes per seed and aces. */
    public record Games(int[] strokes, int aces, int notHoled) {
        public double mean() {
            double sum = 0;
            for (int s : strokes) sum += s;
            return strokes.length == 0 ? Double.NaN : sum / strokes.length;
        }
    }

    /** A hole's result: its games and sweep, and whether it passes. */
    public record HoleResult(int number, String name, int par, Games medium, Games pro, double aceSweepShare, boolean aceHole) {
        public boolean mediumPasses() {
            return medium.mean() <= par + MEDIUM_ALLOWANCE + 1e-9;
        }

        public boolean proPasses() {
            return pro.mean() <= par + 1e-9;
        }

        public boolean acesPass() {
            return aceHole || pro.aces() <= PRO_ACE_SHARE * pro.strokes().length + 1e-9;
        }

        public boolean passes() {
            return mediumPasses() && proPasses() && acesPass() && medium.notHoled() == 0 && pro.notHoled() == 0;
        }
    }

    /** The settings of a check: seeds 1..seeds, the most strokes and simulations per game, the sweep's grid. */
    public record Settings(int seeds, int maxStrokes, long budget, int sweepAngles, int sweepSpeeds, int threads) {
    }

    private ParCheck() {
    }

    /** Plays every chosen hole (1-based numbers; empty: all). */
    public static List<HoleResult> run(Round round, List<Integer> holes, List<Integer> aceHoles, Opponent medium, Opponent pro,
                                       Settings settings) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, settings.threads()));
        try {
            List<Future<HoleResult>> futures = new ArrayList<>();
            for (int i = 0; i < round.size(); i++) {
                int number = i + 1;
                if (!holes.isEmpty() && !holes.contains(number)) continue;
                Round.Hole h = round.hole(i);
                futures.add(pool.submit(() -> new HoleResult(number, h.world().course().name(), h.par(),
                        games(h.world(), medium, settings), games(h.world(), pro, settings),
                        aceSweepShare(h.world(), settings.sweepAngles(), settings.sweepSpeeds()), aceHoles.contains(number))));
            }
            List<HoleResult> out = new ArrayList<>();
            for (Future<HoleResult> f : futures) {
                try {
                    out.add(f.get());
                } catch (java.util.concurrent.ExecutionException e) {
                    throw new IllegalStateException(e.getCause());
                }
            }
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /** The opponent's games on a world over seeds 1..N. */
    static Games games(World world, Opponent opponent, Settings settings) {
        int[] strokes = new int[settings.seeds()];
        int aces = 0, notHoled = 0;
        PlayConditions conditions = new PlayConditions(new NoiseModel(0, opponent.velocityNoise()), false);
        for (int seed = 1; seed <= settings.seeds(); seed++) {
            Bot bot = Bots.create(opponent.bot());
            Playthrough.Result r = Playthrough.play(bot, world, SimulationSettings.DEFAULT, settings.maxStrokes(), settings.budget(),
                    seed, CancellationToken.withTimeLimit(120), BotProgress.NONE, conditions);
            strokes[seed - 1] = r.strokes();
            if (r.holed() && r.strokes() == 1) aces++;
            if (!r.holed()) notHoled++;
        }
        return new Games(strokes, aces, notHoled);
    }

    /** The share of a sweep of first strokes (angles x speeds up to the course's maximum) that hole in one. */
    public static double aceSweepShare(World world, int angles, int speeds) {
        if (angles <= 0 || speeds <= 0) return Double.NaN;
        Simulator sim = new Simulator(world, SimulationSettings.DEFAULT);
        double x = world.course().start().x(), y = world.course().start().y(), max = world.physics().maxSpeed();
        int holed = 0;
        for (int a = 0; a < angles; a++) {
            double t = 2 * Math.PI * a / angles;
            for (int s = 1; s <= speeds; s++) {
                double v = max * s / speeds;
                if (sim.simulate(x, y, v * Math.cos(t), v * Math.sin(t)).outcome() == Outcome.HOLED) holed++;
            }
        }
        return (double) holed / (angles * speeds);
    }

    /** The results as a Markdown table with a summary line. */
    public static String table(String roundName, List<HoleResult> results, Opponent medium, Opponent pro, Settings s) {
        StringBuilder t = new StringBuilder();
        t.append(String.format(java.util.Locale.ROOT, "%s: medium = %s, pro = %s, seeds 1..%d, at most %d strokes and %d simulations a game.%n%n",
                roundName, medium, pro, s.seeds(), s.maxStrokes(), s.budget()));
        t.append("| hole | name | par | medium mean | pro mean | pro aces | one-stroke sweep | verdict |\n");
        t.append("|---:|---|---:|---:|---:|---:|---:|---|\n");
        int passed = 0;
        for (HoleResult r : results) {
            List<String> why = new ArrayList<>();
            if (!r.mediumPasses()) why.add("medium over par + 1.5");
            if (!r.proPasses()) why.add("pro over par");
            if (!r.acesPass()) why.add("pro aces too often");
            if (r.medium().notHoled() + r.pro().notHoled() > 0) why.add("not holed in " + (r.medium().notHoled() + r.pro().notHoled()) + " games");
            if (why.isEmpty()) passed++;
            t.append(String.format(java.util.Locale.ROOT, "| %d | %s | %d | %.1f | %.1f | %d of %d%s | %.2f%% | %s |%n", r.number(), r.name(), r.par(),
                    r.medium().mean(), r.pro().mean(), r.pro().aces(), r.pro().strokes().length, r.aceHole() ? " (ace hole)" : "",
                    100 * r.aceSweepShare(), why.isEmpty() ? "ok" : String.join("; ", why)));
        }
        t.append(String.format(java.util.Locale.ROOT, "%n%d of %d holes pass.%n", passed, results.size()));
        return t.toString();
    }
}
