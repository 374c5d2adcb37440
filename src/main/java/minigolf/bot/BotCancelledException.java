package minigolf.bot;

/** Thrown out of {@link Bot#nextShot} when its {@link CancellationToken} was cancelled. */
public final class BotCancelledException extends RuntimeException {
    public BotCancelledException() {
        super("the bot was cancelled", null, false, false);
    }
}
