package minigolf.bot;

/**
 * Thrown by {@link CountingSimulator} when the simulation budget is spent. Bots catch it (see
 * {@link SearchBot}) and return the best shot seen so far; callers of a bot never see it.
 */
public final class BudgetExhaustedException extends RuntimeException {
    public BudgetExhaustedException(long budget) {
        super("the simulation budget of " + budget + " is spent", null, false, false);
    }
}
