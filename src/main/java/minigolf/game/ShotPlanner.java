package minigolf.game;

import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * The one interface through which the game asks a bot for a shot (the bots themselves live in
 * minigolf.bot; {@link BotCatalog} adapts them). Called on a worker thread, never the render thread.
 */
public interface ShotPlanner {
    /** Progress and cancellation, shared with the render thread. */
    interface Control {
        /** Reports progress in [0, 1] and a short line such as "simulated 120 of 2000 shots". */
        void progress(double fraction, String message);

        boolean isCancelled();

        /** Runs {@code action} when the turn is cancelled (at once if it already is); for bots with their own token. */
        void whenCancelled(Runnable action);

        /** The route the bot intends from the ball to the hole, for drawing while it thinks. */
        default void plan(java.util.List<double[]> points) {
        }
    }

    String name();

    /**
     * The velocity (vx, vy) for a putt or (vx, vy, vz), vz &gt;= 0, for a chip, to hit the ball at (x, y)
     * with; its whole length must not exceed the course's maxSpeed.
     * The same arguments (seed included) give the same shot.
     *
     * @throws java.util.concurrent.CancellationException if {@code control.isCancelled()} became true
     */
    double[] plan(World world, SimulationSettings settings, double x, double y, int strokesTaken, long seed, Control control);

    /**
     * As {@link #plan(World, SimulationSettings, double, double, int, long, Control)} under
     * {@code conditions}: the game's noise (the "realistic" setting) and hidden friction. Planners
     * that model neither ignore them.
     */
    default double[] plan(World world, SimulationSettings settings, double x, double y, int strokesTaken, long seed,
                          BotConditions conditions, Control control) {
        return plan(world, settings, x, y, strokesTaken, seed, control);
    }
}
