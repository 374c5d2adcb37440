package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import minigolf.online.Json;
import minigolf.online.RoomEvent;
import minigolf.online.client.HeadlessPlayer;

/** A headless player run to the end of its round in a test, and its card checked against the server's store. */
final class HeadlessRuns {
    private HeadlessRuns() {
    }

    /**
     * Runs {@code player} on a thread of its own; fails if it is still waiting after 90 s (with its last
     * messages and what it said) or stopped with an error. Returns its final card.
     */
    static JsonNode playToTheEnd(HeadlessPlayer player, List<String> out, List<String> said) throws Exception {
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                player.run();
            } catch (Exception | Error e) {
                failed.set(e);
            }
        }, "headless-test-player");
        t.setDaemon(true);
        t.start();
        t.join(TimeUnit.SECONDS.toMillis(90));
        assertFalse(t.isAlive(), "the player is still waiting: " + player.recentMessages() + "; said " + said);
        assertEquals(null, failed.get());
        return Json.parse(out.get(out.size() - 1));
    }

    /** Every stroke on the one-seat {@code card} stored once: the stored events are its strokes, numbered 1, 2, ... */
    static void assertEveryStrokeStoredOnce(GameServer server, JsonNode card) throws Exception {
        int strokes = card.get("players").get(0).get("total").asInt();
        List<String> events = server.store().events(card.get("room").asText());
        assertEquals(strokes, events.size(), "stored strokes against the card");
        for (int i = 0; i < events.size(); i++) assertEquals(i + 1, RoomEvent.parse(Json.parse(events.get(i)), 1).seq());
    }
}
