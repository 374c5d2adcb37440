package minigolf.online.store;

/** The database could not be opened or used: one line naming the database and the problem. */
public final class StoreException extends Exception {
    public StoreException(String message, Throwable cause) {
        super(message, cause);
    }
}
