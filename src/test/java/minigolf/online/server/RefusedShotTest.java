package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import minigolf.online.Json;
import minigolf.online.RoomEvent;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A headless player (the {@code join} client and the benchmark's players) whose shot the server
 * refuses tries it again instead of waiting forever. Here the refusal is the rate limit: half a
 * message a second with a burst of one, so the shot that follows the room's creation at once is
 * dropped with {@code rate-limited}. Before the fix the player kept waiting for a stroke that was
 * never played, and so did its room (found by bench-server: one room of 62 stopped at its first
 * stroke).
 */
class RefusedShotTest {
    @TempDir
    Path dir;

    @Test
    void aShotRefusedByTheRateLimitIsSentAgainAndTheRoundEnds() throws Exception {
        StringWriter log = new StringWriter();
        ServerOptions o = TestServers.options(dir.resolve("s.db").toString()).withRate(0.5, 1);
        try (GameServer server = TestServers.start(o, log)) {
            List<String> out = Collections.synchronizedList(new ArrayList<>()), said = Collections.synchronizedList(new ArrayList<>());
            HeadlessPlayer player = new HeadlessPlayer(new HeadlessPlayer.Options(OnlineClient.uri("127.0.0.1:" + server.port()),
                    "flat", 1, List.of(), false, null, "Ann", "straight", null, 0), out::add, said::add, null);
            AtomicReference<Throwable> failed = new AtomicReference<>();
            Thread t = new Thread(() -> {
                try {
                    player.run();
                } catch (Exception | Error e) {
                    failed.set(e);
                }
            }, "refused-shot-player");
            t.setDaemon(true);
            t.start();
            t.join(TimeUnit.SECONDS.toMillis(90));
            assertFalse(t.isAlive(), "the player is still waiting: " + player.recentMessages() + "; said " + said);
            assertEquals(null, failed.get());
            assertTrue(said.stream().anyMatch(l -> l.contains("too many messages")), "the shot was refused at first: " + said);
            JsonNode card = Json.parse(out.get(out.size() - 1));
            int strokes = card.get("players").get(0).get("total").asInt();
            String code = card.get("room").asText();
            // Every stroke stored once: the stored events are the card's strokes, numbered 1, 2, ...
            List<String> events = server.store().events(code);
            assertEquals(strokes, events.size(), "stored strokes against the card");
            for (int i = 0; i < events.size(); i++) assertEquals(i + 1, RoomEvent.parse(Json.parse(events.get(i)), 1).seq());
        }
    }
}
