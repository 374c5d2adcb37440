package minigolf.bot.play;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import minigolf.bot.Bot;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.friction.FrictionEstimator;
import minigolf.bot.friction.FrictionPrior;
import minigolf.bot.noise.PlayedStroke;
import minigolf.bot.noise.ShotNoise;
import minigolf.bot.search.SearchBot;
import minigolf.physics.Landing;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * A bot plays a course from its start, stroke by stroke, with the game's rules: water or out of
 * bounds costs a penalty stroke and the ball goes back where the stroke began (where the ball lay,
 * not the noisy start). The shots played are the game's own and are not counted as bot simulations.
 *
 * <p>Under {@link PlayConditions}: the bot's choice is perturbed by {@link ShotNoise} before it is
 * played in the true world (the bot's own simulations stay exact); with hidden friction the bot
 * simulates a world holding only the prior ({@link FrictionPrior}), re-fitted after each stroke by
 * a {@link FrictionEstimator} from what the bot knows: where the ball lay, the shot it chose and
 * where the ball came to rest. The estimator's simulations count as the bot's.
 */
public final class Playthrough {
    /** Mixed into the game's seed for the noise stream, so the bot's seeds stay those of a noiseless game. */
    private static final long NOISE_SEED_SALT = 0x6E6F6973652D3132L;

    /**
     * One stroke: the shot played, what happened, the simulations the bot used to choose it, the
     * shot the bot chose ({@code intended}), where the stroke really started, and the friction
     * estimate after it: the scale of the prior for the course's default friction (NaN when friction
     * is not hidden) and for every zone in order (empty when not hidden or without zones).
     */
    public record PlayedShot(Shot shot, ShotResult result, long simulations, Shot intended, double startX,
                             double startY, double frictionScale, List<Double> zoneScales) {
        /** A stroke played exactly as chosen. */
        public PlayedShot(Shot shot, ShotResult result, long simulations) {
            this(shot, result, simulations, shot, Double.NaN, Double.NaN, Double.NaN, List.of());
        }

        public PlayedShot {
            zoneScales = List.copyOf(zoneScales);
        }
    }

    /**
     * @param strokes shots played plus penalty strokes
     * @param timedOut whether the game stopped because the token's time limit ran out
     * @param botErrors errors the bot recovered from (see {@link SearchBot}): empty unless it has a bug
     */
    public record Result(boolean holed, int strokes, long simulations, long wallNanos, List<PlayedShot> shots,
                         boolean timedOut, List<String> botErrors) {
        public Result(boolean holed, int strokes, long simulations, long wallNanos, List<PlayedShot> shots) {
            this(holed, strokes, simulations, wallNanos, shots, false, List.of());
        }
    }

    private Playthrough() {
    }

    /** A game without noise, friction known. */
    public static Result play(Bot bot, World world, SimulationSettings settings, int maxStrokes, long budget,
                              long seed, CancellationToken token, BotProgress progress) {
        return play(bot, world, settings, maxStrokes, budget, seed, token, progress, PlayConditions.NONE);
    }

    /**
     * Plays until holed, until {@code maxStrokes} shots are played, or until the budget or the
     * token's time limit ({@link CancellationToken#withTimeLimit}, for the whole game) is spent
     * (the stroke during which it ran out is still played with the bot's best shot).
     */
    public static Result play(Bot bot, World world, SimulationSettings settings, int maxStrokes, long budget,
                              long seed, CancellationToken token, BotProgress progress, PlayConditions conditions) {
        return play(bot, world, settings, maxStrokes, budget, seed, token, progress, conditions, 1);
    }

    /**
     * {@link #play(Bot, World, SimulationSettings, int, long, long, CancellationToken, BotProgress, PlayConditions)}
     * with the bot's sweeps spread over {@code threads} threads ({@link CountingSimulator#spreadOver}): the
     * same game for any number, sooner where cores are free.
     */
    public static Result play(Bot bot, World world, SimulationSettings settings, int maxStrokes, long budget,
                              long seed, CancellationToken token, BotProgress progress, PlayConditions conditions,
                              int threads) {
        long started = System.nanoTime();
        FrictionEstimator estimator = conditions.hideFriction() ? new FrictionEstimator(FrictionPrior.scaled(world, 1)) : null;
        CountingSimulator counting = new CountingSimulator(estimator != null ? estimator.world() : world, settings,
                budget, token, progress);
        counting.spreadOver(threads);
        CountingSimulator botSim = counting;
        Simulator game = new Simulator(world, settings);
        ShotNoise noise = new ShotNoise(conditions.noise(), world, seed ^ NOISE_SEED_SALT);
        SplittableRandom seeds = new SplittableRandom(seed);
        double x = world.course().start().x(), y = world.course().start().y();
        List<PlayedShot> played = new ArrayList<>();
        int strokes = 0;
        boolean holed = false;
        // The course clock: it starts at 0 and runs on through each stroke's wait and its own time.
        double clock = 0;
        Bot player = TimedBot.forWorld(bot, world);
        // The course as the strokes so far left it (bricks broken): the bot plans on it, the stroke is played on it.
        World now = world;
        while (played.size() < maxStrokes && !holed) {
            long before = counting.count();
            botSim = botSim.inState(now.state());
            if (game.world() != now) game = new Simulator(now, settings);
            botSim.setClock(clock);
            Shot intended = player.nextShot(new BotRequest(botSim, x, y, strokes, seeds.nextLong(), conditions.noise(), clock));
            intended = counting.limit(intended);
            PlayedStroke stroke = conditions.noise().isNone() ? new PlayedStroke(x, y, intended) : noise.play(x, y, intended);
            Shot shot = stroke.shot().withWait(intended.waitSeconds());
            ShotResult result = CountingSimulator.play(game, clock, stroke.x(), stroke.y(), shot, null);
            clock += intended.waitSeconds() + result.time();
            now = now.withState(result.state());
            if (estimator != null && estimator.observe(counting,
                    new FrictionEstimator.Observation(x, y, intended, result.endX(), result.endY()), result.outcome())) {
                botSim = counting.variant(estimator.world(), true);
            }
            played.add(new PlayedShot(shot, result, counting.count() - before, intended, stroke.x(), stroke.y(),
                    estimator != null ? estimator.scale() : Double.NaN, estimator != null ? zoneScales(estimator) : List.of()));
            strokes++;
            if (result.outcome() == Outcome.HOLED) {
                holed = true;
            } else {
                Landing landing = Landing.of(world, result, x, y);
                strokes += landing.penalty();
                x = landing.x();
                y = landing.y();
            }
            if (counting.remaining() <= 0 || token.timeUp()) break;
        }
        return new Result(holed, strokes, counting.count(), System.nanoTime() - started, List.copyOf(played),
                !holed && token.timeUp(), counting.errors());
    }

    private static List<Double> zoneScales(FrictionEstimator estimator) {
        double[] regions = estimator.regionScales();
        List<Double> zones = new ArrayList<>();
        for (int i = 1; i < regions.length; i++) zones.add(regions[i]);
        return zones;
    }
}
