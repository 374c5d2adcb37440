package minigolf.bot;

/**
 * Progress reports for a progress indicator. Called on the bot's own thread, at most every
 * {@link CountingSimulator#PROGRESS_INTERVAL} simulations and when the bot changes phase; an
 * implementation must be quick and thread-safe towards its UI.
 */
@FunctionalInterface
public interface BotProgress {
    BotProgress NONE = (simulations, budget, phase) -> { };

    /**
     * @param simulations simulations used so far (across the whole game, as the budget counts)
     * @param budget      the budget ({@code Long.MAX_VALUE} when unlimited)
     * @param phase       what the bot is doing, e.g. "sweep" or "refine"
     */
    void update(long simulations, long budget, String phase);

    /**
     * The path the bot intends to take from the ball to the hole (course coordinates, ball first,
     * the hole last), so a UI can draw it while the bot thinks. Bots without a route report nothing.
     */
    default void plan(java.util.List<double[]> points) {
    }
}
