package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
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
            JsonNode card = HeadlessRuns.playToTheEnd(player, out, said);
            assertTrue(said.stream().anyMatch(l -> l.contains("too many messages")), "the shot was refused at first: " + said);
            HeadlessRuns.assertEveryStrokeStoredOnce(server, card);
        }
    }
}
