package minigolf.bot;

/**
 * A player that chooses the next shot. The game calls it from a worker thread; the command line
 * ({@code solve}, {@code experiment}) calls it in a loop until the ball is holed.
 *
 * <p>Contract: every simulated shot goes through {@link BotRequest#simulator()} (it counts them,
 * enforces the budget and checks cancellation); with the same request (seed included) a bot returns
 * the same shot. A bot whose budget runs out returns the best shot it has seen (never throws
 * {@link BudgetExhaustedException} to its caller); a cancelled bot throws {@link BotCancelledException}.
 */
public interface Bot {
    /** The name used on the command line and in the game's menu, e.g. {@code planner}. */
    String name();

    /** The shot to play from the request's ball position. */
    Shot nextShot(BotRequest request);
}
