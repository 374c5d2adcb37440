package minigolf.editor;

import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;
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

    private final AtomicBoolean cancelled = new AtomicBoolean();
    private volatile Result result;
    private volatile String failure;
    private volatile double progress;
    private final Thread thread;

    private BotCheck(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed) {
        thread = new Thread(() -> {
            try {
                result = play(planner, world, settings, maxStrokes, seed, control());
            } catch (CancellationException e) {
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
        Simulator game = new Simulator(world, settings);
        double x = world.course().start().x(), y = world.course().start().y();
        int strokes = 0;
        for (int shot = 0; shot < maxStrokes; shot++) {
            double[] v = planner.plan(world, settings, x, y, strokes, seed + 31L * shot, control);
            ShotResult r = game.simulate(x, y, v[0], v[1]);
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

    private ShotPlanner.Control control() {
        return new ShotPlanner.Control() {
            public void progress(double fraction, String message) {
                progress = fraction;
            }

            public boolean isCancelled() {
                return cancelled.get();
            }

            public void whenCancelled(Runnable action) {
                if (cancelled.get()) action.run();
            }
        };
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

    public double progress() {
        return progress;
    }

    public void cancel() {
        cancelled.set(true);
    }

    /** Waits for the worker (tests and the command line). */
    public void join() throws InterruptedException {
        thread.join();
    }
}
