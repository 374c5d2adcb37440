package minigolf.editor;

import java.util.List;
import java.util.concurrent.CancellationException;
import minigolf.bot.NoiseModel;
import minigolf.game.BotConditions;
import minigolf.game.BotControl;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerStatus;
import minigolf.game.ShotPlanner;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * "Ask a bot": a bot plays the edited course from the start with the game's rules (a penalty
 * stroke and back to where the stroke began after water or out of bounds) until it holes out or
 * reaches the stroke limit (penalties count towards it, as in the game). It is played as a game
 * with one bot player, under the player's settings: with the "realistic" noise the strokes stray
 * (seeded), with hidden friction the bot sees only the prior and learns from its strokes. Runs on a
 * worker thread; the window polls {@link #isDone()}.
 */
public final class BotCheck {
    /** What the bot achieved: holed or not, and the strokes it took (penalties included). */
    public record Result(boolean holed, int strokes, String bot, Conditions conditions) {
        public Result(boolean holed, int strokes, String bot) {
            this(holed, strokes, bot, Conditions.NONE);
        }

        public String describe() {
            String how = conditions.describe();
            return (holed ? bot + " holed it in " + strokes + (strokes == 1 ? " stroke" : " strokes")
                    : bot + " did not hole it within " + strokes + " strokes") + (how.isEmpty() ? "" : " (" + how + ")");
        }
    }

    /** The player's settings the check is played under: the noise and whether friction is hidden from the bot. */
    public record Conditions(NoiseModel noise, boolean hideFriction) {
        public static final Conditions NONE = new Conditions(NoiseModel.NONE, false);

        public Conditions {
            if (noise == null) noise = NoiseModel.NONE;
        }

        String describe() {
            String n = noise.isNone() ? "" : "realistic";
            String f = hideFriction ? "friction hidden" : "";
            return n.isEmpty() || f.isEmpty() ? n + f : n + ", " + f;
        }
    }

    /** Shared with the bot: the cancel reaches its token (before, it only set a flag nobody read). */
    private final BotControl control = new BotControl();
    private volatile Result result;
    private volatile String failure;
    private volatile int strokes;
    private final Thread thread;

    private BotCheck(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                     Conditions conditions) {
        thread = new Thread(() -> {
            try {
                result = play(planner, world, settings, maxStrokes, seed, conditions, control, n -> strokes = n);
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
        return start(planner, world, settings, maxStrokes, seed, Conditions.NONE);
    }

    /** Starts a check on a worker thread, under the player's noise and hidden-friction settings. */
    public static BotCheck start(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                                 Conditions conditions) {
        BotCheck c = new BotCheck(planner, world, settings, maxStrokes, seed, conditions);
        c.thread.start();
        return c;
    }

    /** Plays on this thread. */
    public static Result play(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                              ShotPlanner.Control control) {
        return play(planner, world, settings, maxStrokes, seed, Conditions.NONE, control, n -> { });
    }

    /** Plays on this thread under {@code conditions}. */
    public static Result play(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                              Conditions conditions, ShotPlanner.Control control) {
        return play(planner, world, settings, maxStrokes, seed, conditions, control, n -> { });
    }

    /** Plays on this thread, telling {@code strokesTaken} the strokes so far before each stroke. */
    static Result play(ShotPlanner planner, World world, SimulationSettings settings, int maxStrokes, long seed,
                       Conditions conditions, ShotPlanner.Control control, java.util.function.IntConsumer strokesTaken) {
        // The game's own rules and noise: one bot player, the noise stream seeded by the check's seed.
        Game game = new Game(world, settings, List.of(Player.bot(planner.name(), planner.name())), maxStrokes,
                conditions.noise(), seed);
        for (int shot = 0; !game.isOver(); shot++) {
            strokesTaken.accept(game.player(0).total());
            if (control.isCancelled()) throw new CancellationException();
            double[] v = planner.plan(world, settings, game.player(0).x(), game.player(0).y(), game.player(0).total(),
                    seed + 31L * shot, BotConditions.of(game, 0, conditions.hideFriction()), control);
            game.play(v[0], v[1], v.length > 2 ? v[2] : 0); // a chip when the bot chose one
        }
        return new Result(game.player(0).status() == PlayerStatus.HOLED, game.player(0).total(), planner.name(),
                conditions);
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

    /** Stops the bot (its token is cancelled: no simulation starts after it); the check ends "cancelled". */
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
