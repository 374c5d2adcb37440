package minigolf.online;

/**
 * A message the receiver refuses: {@code code} is one of the protocol's error codes
 * (docs/online.md, "Errors"), the message one line for a person.
 */
public final class ProtocolException extends Exception {
    private final String code;

    public ProtocolException(String code, String message) {
        super(message);
        this.code = code;
    }

    public String code() {
        return code;
    }
}
