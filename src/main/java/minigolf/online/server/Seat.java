package minigolf.online.server;

import minigolf.online.store.StoredSeat;

/**
 * A seat in a room: who sits there and whether they are connected. Touched only on the room's thread.
 * {@code awaySinceMs} is when a person's connection dropped (0 while connected, and for bots);
 * {@code gone} once they left for good.
 */
final class Seat {
    final int index;
    String name;
    final boolean bot;
    final String level;
    String tokenHash;
    Client client;
    long awaySinceMs;
    boolean gone;

    Seat(int index, String name, boolean bot, String level, String tokenHash) {
        this.index = index;
        this.name = name;
        this.bot = bot;
        this.level = level;
        this.tokenHash = tokenHash;
    }

    boolean isTaken() {
        return name != null;
    }

    /** A person whose connection is gone (dropped or left); bots are always there. */
    boolean isAway() {
        return !bot && isTaken() && client == null;
    }

    StoredSeat stored() {
        return new StoredSeat(index, name, bot, level, tokenHash, gone);
    }
}
