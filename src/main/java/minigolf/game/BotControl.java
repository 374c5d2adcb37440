package minigolf.game;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * What the render thread sees of a thinking bot and how it stops it: progress, a line of text, the
 * route the bot intends, and Cancel. Shared by the game's {@link BotTurn} and the editor's "Ask a
 * bot", so both show the same bar and both cancels reach the bot's own token.
 */
public final class BotControl implements ShotPlanner.Control {
    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final List<Runnable> cancelActions = new CopyOnWriteArrayList<>();
    private volatile double progress;
    private volatile String message = "thinking";
    private volatile List<double[]> plan = List.of();

    @Override
    public void progress(double fraction, String text) {
        progress = Double.isFinite(fraction) ? Math.max(0, Math.min(1, fraction)) : 0;
        if (text != null) message = text;
    }

    @Override
    public void plan(List<double[]> points) {
        plan = points == null ? List.of() : List.copyOf(points);
    }

    @Override
    public boolean isCancelled() {
        return cancelled.get();
    }

    @Override
    public void whenCancelled(Runnable action) {
        cancelActions.add(action);
        if (cancelled.get()) action.run();
    }

    /** Stops the bot: its token is cancelled at once, so no simulation starts after it (CountingSimulatorTest). */
    public void cancel() {
        if (!cancelled.getAndSet(true)) cancelActions.forEach(Runnable::run);
    }

    public double progress() {
        return progress;
    }

    public String message() {
        return message;
    }

    /** The latest route the bot reported (ball first, hole last), or an empty list. */
    public List<double[]> plan() {
        return plan;
    }
}
