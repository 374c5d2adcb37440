package minigolf.online;

import java.util.List;

/** What a client may send (docs/online.md, "Client messages"); {@link ClientMessages} reads and checks them. */
public sealed interface ClientMessage {
    /** Opens a room on {@code course} (a course or a round) with {@code seats} seats, {@code bots} of them the server's bots. */
    record Create(String name, String course, int seats, List<String> bots, boolean listed, int strokeLimit)
            implements ClientMessage {
    }

    /** Takes a free seat in a room. */
    record Join(String room, String name) implements ClientMessage {
    }

    /** Takes back one's seat after a dropped connection. */
    record Resume(String room, String token) implements ClientMessage {
    }

    /**
     * A stroke: the aim over the ground (its length is the speed, m/s), the loft in degrees and the
     * wait in seconds. {@code seq} is the number of strokes and pick-ups the room has had as the
     * client saw it: a shot sent twice, or sent on an old view, is refused.
     */
    record Shot(long seq, double vx, double vy, double loft, double waitSeconds) implements ClientMessage {
    }

    record Chat(String text) implements ClientMessage {
    }

    /** Leaves the room for good: the seat is picked up on every hole from now on. */
    record Leave() implements ClientMessage {
    }

    record Ping() implements ClientMessage {
    }

    /** Asks for the room's whole state again (a client that missed an event). */
    record Sync() implements ClientMessage {
    }
}
