package minigolf.classic;

/**
 * A classic track file that cannot be imported. The message is one line that names the file, the
 * line and what is wrong, e.g. {@code Chess.track: line 4 (T): tile 1226 of 1225: the map data
 * goes on after the last tile}. Never quotes more of the file than the offending character.
 */
public final class TrackFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    public TrackFormatException(String message) {
        super(message);
    }
}
