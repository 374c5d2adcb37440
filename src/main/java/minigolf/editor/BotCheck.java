package minigolf.editor;

import java.util.concurrent.CancellationException;
import minigolf.game.BotControl;
import minigolf.game.ShotPlanner;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * "Ask a bot": a bot plays the edited course from the start with the game's rules (a penalty
 * stroke and back to where the stroke began after water or out of bounds) until it holes out or
 * reaches the stroke limit. Runs on a worker thread; the window polls {@link #isDone()}.
 */
public final class BotCheck {
    /** What the bot achieved: holed or not, and the strokes it took (penalties included). */
    public record Result(boolean holed, int strokes, String bot) {
        public String describe() {
            return holed ? bot + " holed it in " + strokes + (strokes == 1 ? " stroke" : " strokes")
                    : bot + " did not hole it within " + strokes + " strokes";
        }
    }

    /** Shared with the bot: the cancel reaches its token (before, it only set a flag nobody read). */
    private final BotControl control = new BotControl();
    private volatile Result result;
    private volatile String failure;
    private volatile int strokes;
    private final Thread thread;

    private BotCheck(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed) {
        thread = new Thread(() -> {
            try {
                result = play(planner, world, settings, maxStrokes, seed, control, n -> strokes = n);
            } catch (CancellationException | minigolf.bot.BotCancelledException e) {
                failure = "cancelled";
            } catch (RuntimeException e) {
                failure = planner.name() + " failed: " + e.getMessage();
            }
        }, "editor-bot");
        thread.setDaemon(true);
    }

    /** Starts a check on a worker thread. */
    public static BotCheck start(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed) {
        BotCheck c = new BotCheck(planner, world, settings, maxStrokes, seed);
        c.thread.start();
        return c;
    }

    /** Plays on this thread. */
    public static Result play(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                              ShotPlanner.Control control) {
        return play(planner, world, settings, maxStrokes, seed, control, n -> { });
    }

    /** Plays on this thread, telling {@code strokesTaken} the strokes so far before each stroke. */
    static Result play(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                       ShotPlanner.Control control, java.util.function.IntConsumer strokesTaken) {
        Simulator game = new Simulator(world, settings);
        double x = world.course().start().x(), y = world.course().start().y();
        int strokes = 0;
        for (int shot = 0; shot < maxStrokes; shot++) {
            strokesTaken.accept(strokes);
            if (control.isCancelled()) throw new CancellationException();
            double[] v = planner.plan(world, settings, x, y, strokes, seed + 31L * shot, control);
            ShotResult r = game.simulate(x, y, v[0], v[1], v.length > 2 ? v[2] : 0); // a chip when the bot chose one
            strokes++;
            if (r.outcome() == Outcome.HOLED) return new Result(true, strokes, planner.name());
            if (r.outcome().isPenalty()) {
                strokes++;
            } else {
                x = r.endX();
                y = r.endY();
            }
        }
        return new Result(false, strokes, planner.name());
    }

    public boolean isDone() {
        return result != null || failure != null;
    }

    /** The result, or null while running or after a failure. */
    public Result result() {
        return result;
    }

    public String failure() {
        return failure;
    }

    /** The current stroke's progress (each stroke fills the bar again). */
    public double progress() {
        return control.progress();
    }

    /** "stroke 3: sweep: 420 simulations" */
    public String message() {
        return "stroke " + (strokes + 1) + ": " + control.message();
    }

    /** The route the bot intends from where the ball lies now, or an empty list. */
    public java.util.List<double[]> plan() {
        return control.plan();
    }

    /** Stops the bot within about 50 ms (its token is cancelled); the check ends "cancelled". */
    public void cancel() {
        control.cancel();
    }

    /** Waits at most {@code millis} for the worker. */
    public void join(long millis) throws InterruptedException {
        thread.join(millis);
    }

    /** Waits for the worker (tests and the command line). */
    public void join() throws InterruptedException {
        thread.join();
    }
}
