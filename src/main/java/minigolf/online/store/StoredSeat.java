package minigolf.online.store;

/**
 * A seat as the database keeps it. {@code tokenHash} is the SHA-256 of the seat's token (hex), null
 * for the server's bots; {@code level} the bot level of a bot seat; {@code gone} once the player left.
 */
public record StoredSeat(int seat, String name, boolean bot, String level, String tokenHash, boolean gone) {
}
