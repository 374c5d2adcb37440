package minigolf.bot;

import java.util.Locale;

/**
 * Thrown by {@link CountingSimulator} when the simulation budget is spent, and by
 * {@link CancellationToken#throwIfCancelled()} when the wall-time limit has run out. Bots catch it
 * (see {@link minigolf.bot.search.SearchBot}) and return the best shot seen so far; callers of a
 * bot never see it.
 */
public final class BudgetExhaustedException extends RuntimeException {
    public BudgetExhaustedException(long budget) {
        this("the simulation budget of " + budget + " is spent");
    }

    private BudgetExhaustedException(String message) {
        super(message, null, false, false);
    }

    static BudgetExhaustedException timeUp(double seconds) {
        return new BudgetExhaustedException(String.format(Locale.ROOT, "the time limit of %.3g s is spent", seconds));
    }
}
