package minigolf.game;

import java.util.concurrent.CancellationException;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * One bot decision running on its own daemon thread, so the render loop never waits for it. The
 * render thread polls {@link #isDone()}, shows {@link #progress()} and may {@link #cancel()}.
 */
public final class BotTurn {
    private final BotControl control = new BotControl();
    private final Thread thread;
    private volatile double[] shot;
    /** The wait (s) the bot planned before its shot (moving obstacles), 0 when it plays at once. */
    private volatile double waitSeconds;
    private volatile String failure;
    private volatile boolean done;

    public BotTurn(ShotPlanner planner, World world, SimulationSettings settings, double x, double y, int strokesTaken,
                   long seed) {
        this(planner, world, settings, x, y, strokesTaken, seed, BotConditions.NONE);
    }

    /** A turn under {@code conditions}: the game's noise (the robust bot plays for it) and hidden friction. */
    public BotTurn(ShotPlanner planner, World world, SimulationSettings settings, double x, double y, int strokesTaken,
                   long seed, BotConditions conditions) {
        thread = new Thread(() -> {
            try {
                double[] v = planner.plan(world, settings, x, y, strokesTaken, seed, conditions, control);
                if (control.isCancelled()) {
                    failure = "cancelled";
                } else if (v == null || v.length < 2 || v.length > 4 || !java.util.Arrays.stream(v).allMatch(Double::isFinite)
                        || (v.length >= 3 && v[2] < 0) || (v.length == 4 && v[3] < 0)) {
                    failure = planner.name() + " gave no shot";
                } else {
                    double vz = v.length >= 3 ? v[2] : 0;
                    waitSeconds = v.length == 4 ? v[3] : 0;
                    double speed = Math.sqrt(v[0] * v[0] + v[1] * v[1] + vz * vz), max = world.physics().maxSpeed();
                    // A bot may round just past the limit; the game never hits harder than maxSpeed (the whole vector).
                    double k = speed > max ? max / speed : 1;
                    shot = k == 1 ? new double[]{v[0], v[1], vz} : new double[]{v[0] * k, v[1] * k, vz * k};
                }
            } catch (CancellationException | minigolf.bot.BotCancelledException e) {
                failure = "cancelled";
            } catch (RuntimeException | StackOverflowError e) {
                failure = planner.name() + " failed: " + e.getMessage();
            } finally {
                done = true;
            }
        }, "bot-" + planner.name());
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * The seed of a bot's decision in a game: the game's own seed (drawn when it starts) mixed with
     * the hole (0-based), the strokes played on it so far (all players) and the seat. A level draws
     * its error from this seed, so each stroke of each hole is misplayed afresh; with one seed per
     * stroke number and seat, a level's first stroke was struck with the same error on every hole of
     * every round (Hard aced 11 of Meadowbrook's 18 holes, every time).
     */
    public static long seed(long gameSeed, int hole, int strokesPlayed, int seat) {
        long key = ((long) hole * 10_000 + strokesPlayed) * Game.MAX_PLAYERS + seat;
        return new java.util.SplittableRandom(gameSeed ^ key * 0x9E3779B97F4A7C15L).nextLong();
    }

    public boolean isDone() {
        return done;
    }

    public double progress() {
        return done ? 1 : control.progress();
    }

    public String message() {
        return control.message();
    }

    /** The route the bot intends (ball first, hole last), or an empty list. */
    public java.util.List<double[]> plan() {
        return control.plan();
    }

    /** The shot (vx, vy, vz; vz = 0 for a putt) once done and successful, else null. */
    public double[] shot() {
        return shot;
    }

    /** The wait (s) before the shot the bot planned: the course clock runs on this long, then it is hit. */
    public double waitSeconds() {
        return waitSeconds;
    }

    /** Why there is no shot ("cancelled", an error line), or null. */
    public String failure() {
        return failure;
    }

    public void cancel() {
        control.cancel();
    }

    /** Waits for the worker (tests, shutdown). */
    public void join(long millis) throws InterruptedException {
        thread.join(millis);
    }
}
