package minigolf.game;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.play.TimedBot;
import minigolf.bot.friction.FrictionEstimator;
import minigolf.bot.friction.FrictionPrior;
import minigolf.bot.level.Level;
import minigolf.bot.play.Bots;
import minigolf.bot.search.SearchBot;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * The bots the game can seat and watch ("Test bot"), by name. Bots of minigolf.bot are adapted to
 * {@link ShotPlanner} by {@link #fromBot}; each request gets a fresh planner (planners need not be
 * thread-safe). First the opponents by level ({@link #levels()}: easy, medium, hard, pro), what a
 * player chooses from; then every other bot of {@link Bots} by its algorithm's name (the planner
 * first), for experts; last the "straight" putter: the physics guess straight at the hole, with no search.
 */
public final class BotCatalog {
    /** Simulations a bot may spend on one stroke in the game. */
    public static final long BUDGET_PER_STROKE = 20_000;
    /** Wall time a bot may think about one stroke in the game; then it plays its best shot so far. */
    public static final double TIME_LIMIT_PER_STROKE = 20;
    /**
     * Simulations {@code planner-aces}' full search runs through in a second of one core's time, as
     * measured on the project's shared 2-core machine under a load of about 15-20 (planner-aces on
     * the tile courses of seed 47692372: the median of the nine games whose search spent over
     * 100,000, 11,700-16,300; docs/bots.md); a quiet core runs about twice as many
     * (docs/measurements.md).
     */
    static final double FULL_SEARCH_SIMULATIONS_PER_SECOND = 13_000;
    /**
     * The budget of {@code planner-aces}, the strong and slow choice: the simulations its full
     * search (which it runs at any budget, its stages sized to what is left) gets through in the
     * stroke's {@link #TIME_LIMIT_PER_STROKE} at that rate. With 1,000,000 a single stroke's search
     * could run 300,000 simulations and more, over 20 s on a loaded machine, and the time limit cut it
     * at whatever it had found; sized to the time, its search ends and it plays its choice.
     */
    public static final long FULL_SEARCH_BUDGET_PER_STROKE = Math.round(TIME_LIMIT_PER_STROKE * FULL_SEARCH_SIMULATIONS_PER_SECOND);
    /**
     * Threads a bot's sweeps run on while it thinks ({@link CountingSimulator#spreadOver}): the
     * cores but one (left to drawing the game), at most 4, so 1 on a 2-core machine. The shot is
     * the same for any number; only the wait is shorter.
     */
    public static final int THINK_THREADS = Math.max(1, Math.min(4, Runtime.getRuntime().availableProcessors() - 1));
    private static final Map<String, Supplier<ShotPlanner>> PLANNERS = new LinkedHashMap<>();

    /** The opponent a new bot seat starts with. */
    public static final String DEFAULT_OPPONENT = "medium";

    static {
        for (String level : Bots.levels()) registerBot(level, () -> Bots.create(level));
        registerBot(Bots.DEFAULT, () -> Bots.create(Bots.DEFAULT));
        for (String name : Bots.names()) {
            if (!name.equals(Bots.DEFAULT)) registerBot(name, () -> Bots.create(name));
        }
        register("straight", () -> new ShotPlanner() {
            public String name() {
                return "straight";
            }

            public double[] plan(World w, SimulationSettings s, double x, double y, int strokes, long seed, Control c) {
                Shot shot = SearchBot.directGuess(w, x, y).limitedTo(w.physics().maxSpeed());
                return new double[]{shot.vx(), shot.vy(), shot.vz()}; // the game plays chips too
            }
        });
    }

    private BotCatalog() {
    }

    /** Adds a bot under its name (replacing one of the same name). */
    public static synchronized void register(String name, Supplier<ShotPlanner> factory) {
        PLANNERS.put(name, factory);
    }

    /** Adds a minigolf.bot bot: {@code factory} makes a fresh bot per stroke. */
    public static void registerBot(String name, Supplier<Bot> factory) {
        register(name, () -> fromBot(factory.get()));
    }

    public static synchronized List<String> names() {
        return new ArrayList<>(PLANNERS.keySet());
    }

    /** The opponents by level, from the easiest: {@code easy}, {@code medium}, {@code hard}, {@code pro}. */
    public static List<String> levels() {
        return Bots.levels();
    }

    /** A bot's name as a player reads it: "Easy", "Medium", "Hard", "Pro" for the levels, else the name itself. */
    public static String label(String name) {
        return Level.byId(name) == null ? name : Character.toUpperCase(name.charAt(0)) + name.substring(1);
    }

    /** A new planner for the bot with this name, or null if there is none. */
    public static synchronized ShotPlanner planner(String name) {
        Supplier<ShotPlanner> f = PLANNERS.get(name);
        return f == null ? null : f.get();
    }

    /** The simulator of the friction estimated from the bot's own strokes (the prior's when none tells). */
    private static CountingSimulator estimated(CountingSimulator prior, BotConditions conditions) {
        FrictionEstimator estimator = new FrictionEstimator(prior.world());
        for (BotConditions.OwnStroke s : conditions.ownStrokes()) estimator.observe(prior, s.observation(), s.outcome());
        return estimator.world() == prior.world() ? prior : prior.variant(estimator.world(), true);
    }

    /**
     * Adapts a bot: its simulations are counted against {@link #budgetPerStroke}, its thinking
     * limited to {@link #TIME_LIMIT_PER_STROKE}, and both reported as progress.
     */
    /** What a bot may spend on one stroke in the game: {@code planner-aces} the full search's budget, every other bot 20,000. */
    public static long budgetPerStroke(String botName) {
        return botName.equals("planner-aces") ? FULL_SEARCH_BUDGET_PER_STROKE : BUDGET_PER_STROKE;
    }

    public static ShotPlanner fromBot(Bot bot) {
        long budget = budgetPerStroke(bot.name());
        return new ShotPlanner() {
            public String name() {
                return bot.name();
            }

            public double[] plan(World world, SimulationSettings settings, double x, double y, int strokes, long seed,
                                 Control control) {
                return plan(world, settings, x, y, strokes, seed, BotConditions.NONE, control);
            }

            @Override
            public double[] plan(World world, SimulationSettings settings, double x, double y, int strokes, long seed,
                                 BotConditions conditions, Control control) {
                CancellationToken token = CancellationToken.withTimeLimit(TIME_LIMIT_PER_STROKE);
                control.whenCancelled(token::cancel);
                long started = System.nanoTime();
                BotProgress progress = new BotProgress() {
                    public void update(long used, long budget, String phase) {
                        // The bar shows whichever runs out first: the simulations or the time.
                        control.progress(Math.min(1, Math.max((double) used / budget,
                                (System.nanoTime() - started) / 1e9 / TIME_LIMIT_PER_STROKE)), phase + ": " + used + " simulations");
                    }

                    public void plan(List<double[]> points) {
                        control.plan(points);
                    }
                };
                // Hidden friction: the bot simulates the prior, re-fitted to its own strokes (counted in its budget).
                World seen = conditions.hideFriction() ? FrictionPrior.scaled(world, 1) : world;
                CountingSimulator sim = new CountingSimulator(seen, settings, budget, token, progress);
                sim.spreadOver(THINK_THREADS);
                CountingSimulator botSim = conditions.hideFriction() ? estimated(sim, conditions) : sim;
                botSim.setClock(conditions.clock());
                Bot player = TimedBot.forWorld(bot, seen);
                Shot shot = sim.limit(player.nextShot(new BotRequest(botSim, x, y, strokes, seed, conditions.noise(),
                        conditions.clock())));
                // The game plays chips too, and waits the bot's planned time where obstacles move.
                return shot.waitSeconds() > 0 ? new double[]{shot.vx(), shot.vy(), shot.vz(), shot.waitSeconds()}
                        : new double[]{shot.vx(), shot.vy(), shot.vz()};
            }
        };
    }
}
