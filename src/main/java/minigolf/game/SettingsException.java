package minigolf.game;

/**
 * The settings file could not be used: the file's own one-line error (for the terminal:
 * {@code <file>: <field>: <problem>}) and the same in a player's words (for the game's notice:
 * which setting, what it may be in the game's units, what the file has; no file path).
 */
public final class SettingsException extends SaveGameException {
    private static final long serialVersionUID = 1L;
    private final String forPlayer;

    SettingsException(SaveGameException fileError, String forPlayer) {
        super(fileError.sourceName(), fileError.path(), fileError.problem(), fileError.getCause() != null ? fileError.getCause() : fileError);
        this.forPlayer = forPlayer;
    }

    /** One or two sentences a player understands, e.g. "The frame limit is 2000; it must be a whole number from 0 (no limit) to 1000 frames a second." */
    public String forPlayer() {
        return forPlayer;
    }
}
