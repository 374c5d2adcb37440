package minigolf.online;

import java.util.regex.Pattern;

/**
 * The online protocol's version and limits (docs/online.md, "Protocol"). One JSON object per
 * WebSocket text message, both ways; every client message names its {@code type}.
 */
public final class Protocol {
    /** Raised when a message changes meaning; a client of another version is refused with an error. */
    public static final int VERSION = 1;
    /** The WebSocket path on the server's port. */
    public static final String PATH = "/play";

    /** Largest client message the server reads (bytes of UTF-8); a larger one gets an error and is dropped. */
    public static final int MAX_MESSAGE_BYTES = 4096;
    /** Larger frames than this are not even buffered: the connection is closed (1009, message too big). */
    public static final int MAX_FRAME_BYTES = 65536;
    /** Longest chat line, in characters. */
    public static final int MAX_CHAT_CHARS = 200;
    /** Longest wait before a shot (s): for moving obstacles; a course without them plays the same whatever the wait. */
    public static final double MAX_WAIT_SECONDS = 30;
    /** Seats in a room, as in hot seat. */
    public static final int MAX_SEATS = minigolf.game.Game.MAX_PLAYERS;

    /** Room codes: 8 letters and digits without look-alikes (0/O, 1/I/L), drawn with SecureRandom: 31^8, about 2^40. */
    public static final String CODE_ALPHABET = "23456789ABCDEFGHJKMNPQRSTUVWXYZ";
    public static final int CODE_LENGTH = 8;
    public static final Pattern CODE = Pattern.compile("[" + CODE_ALPHABET + "]{" + CODE_LENGTH + "}");
    /** Seat tokens: 128 random bits, base64url without padding (22 characters). */
    public static final Pattern TOKEN = Pattern.compile("[A-Za-z0-9_-]{22}");
    /** Course and round names as the server offers them: file names without .json. */
    public static final Pattern COURSE_NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");

    private Protocol() {
    }
}
