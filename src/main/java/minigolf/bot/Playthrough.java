package minigolf.bot;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * A bot plays a course from its start, stroke by stroke, with the game's rules: water or out of
 * bounds costs a penalty stroke and the ball goes back where the stroke began. The shots played
 * are the game's own and are not counted as bot simulations.
 */
public final class Playthrough {
    /** One stroke: what the bot chose, what happened, and the simulations it used to choose it. */
    public record PlayedShot(Shot shot, ShotResult result, long simulations) {
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

    /**
     * Plays until holed, until {@code maxStrokes} shots are played, or until the budget or the
     * token's time limit ({@link CancellationToken#withTimeLimit}, for the whole game) is spent
     * (the stroke during which it ran out is still played with the bot's best shot).
     */
    public static Result play(Bot bot, World world, SimulationSettings settings, int maxStrokes, long budget,
                              long seed, CancellationToken token, BotProgress progress) {
        long started = System.nanoTime();
        CountingSimulator counting = new CountingSimulator(world, settings, budget, token, progress);
        Simulator game = new Simulator(world, settings);
        SplittableRandom seeds = new SplittableRandom(seed);
        double x = world.course().start().x(), y = world.course().start().y();
        List<PlayedShot> played = new ArrayList<>();
        int strokes = 0;
        boolean holed = false;
        while (played.size() < maxStrokes && !holed) {
            long before = counting.count();
            Shot shot = bot.nextShot(new BotRequest(counting, x, y, strokes, seeds.nextLong()));
            shot = counting.limit(shot);
            ShotResult result = CountingSimulator.play(game, x, y, shot, null);
            played.add(new PlayedShot(shot, result, counting.count() - before));
            strokes++;
            if (result.outcome() == Outcome.HOLED) {
                holed = true;
            } else if (result.outcome().isPenalty()) {
                strokes++;
            } else {
                x = result.endX();
                y = result.endY();
            }
            if (counting.remaining() <= 0 || token.timeUp()) break;
        }
        return new Result(holed, strokes, counting.count(), System.nanoTime() - started, List.copyOf(played),
                !holed && token.timeUp(), counting.errors());
    }
}
