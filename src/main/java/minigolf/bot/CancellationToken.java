package minigolf.bot;

import java.util.function.LongSupplier;

/**
 * Lets another thread (the game's cancel button) stop a bot, and carries the bot's wall-time
 * limit. Bots check it before every simulated shot, every few hundred steps inside a simulated
 * shot, and in any loop of their own that can run longer than a millisecond or so, so a cancel or
 * the end of the time limit takes effect within about a millisecond of the bot's own CPU time.
 *
 * <p>A cancel ends the bot with {@link BotCancelledException}; the end of the time limit is the
 * end of a budget ({@link BudgetExhaustedException}): the bot returns its best shot so far.
 */
public final class CancellationToken {
    /** The clock the time limit runs on, in nanoseconds: {@code System.nanoTime} unless a test gives its own. */
    private final LongSupplier clock;
    private volatile boolean cancelled;
    /** The clock's time at which the time limit ends; meaningful only when {@link #limitNanos} >= 0. */
    private volatile long deadline;
    private volatile long limitNanos = -1;

    /** A token nobody cancels yet, with no time limit. */
    public CancellationToken() {
        this(System::nanoTime);
    }

    /** A token whose time limit (if one is set) runs on {@code nanoClock} (tests: a machine as slow as one likes). */
    public CancellationToken(LongSupplier nanoClock) {
        this.clock = nanoClock;
    }

    /** A token nobody cancels, with no time limit. */
    public static CancellationToken none() {
        return new CancellationToken();
    }

    /** A token whose time limit ends {@code seconds} from now (must be > 0 and finite). */
    public static CancellationToken withTimeLimit(double seconds) {
        CancellationToken token = new CancellationToken();
        token.limitTime(seconds);
        return token;
    }

    /** Starts (or restarts) the time limit: it ends {@code seconds} from now. */
    public void limitTime(double seconds) {
        if (!(seconds > 0) || !Double.isFinite(seconds)) {
            throw new IllegalArgumentException("time limit must be > 0 seconds, got " + seconds);
        }
        long nanos = (long) Math.min(seconds * 1e9, Long.MAX_VALUE / 4.0);
        deadline = clock.getAsLong() + nanos;
        limitNanos = nanos;
    }

    public void cancel() {
        cancelled = true;
    }

    public boolean isCancelled() {
        return cancelled;
    }

    /** Whether a time limit was set and has run out. */
    public boolean timeUp() {
        return limitNanos >= 0 && clock.getAsLong() - deadline >= 0;
    }

    /** The time limit in seconds, or NaN when there is none. */
    public double timeLimitSeconds() {
        return limitNanos >= 0 ? limitNanos / 1e9 : Double.NaN;
    }

    /**
     * @throws BotCancelledException    once {@link #cancel()} has been called
     * @throws BudgetExhaustedException once the time limit has run out
     */
    public void throwIfCancelled() {
        if (cancelled) throw new BotCancelledException();
        if (timeUp()) throw BudgetExhaustedException.timeUp(timeLimitSeconds());
    }
}
