package minigolf.bot;

/**
 * Lets another thread (the game's cancel button) stop a bot. Bots check it before every simulated
 * shot, and in any loop of their own that can run longer than a millisecond or so, so a cancel
 * takes effect within 50 ms.
 */
public final class CancellationToken {
    private volatile boolean cancelled;

    /** A token nobody cancels. */
    public static CancellationToken none() {
        return new CancellationToken();
    }

    public void cancel() {
        cancelled = true;
    }

    public boolean isCancelled() {
        return cancelled;
    }

    /** @throws BotCancelledException once {@link #cancel()} has been called */
    public void throwIfCancelled() {
        if (cancelled) throw new BotCancelledException();
    }
}
