package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import minigolf.online.Json;
import minigolf.online.ProtocolException;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A headless player (the {@code join} client and the benchmark's players) whose shot is lost on its
 * way, so that nothing at all answers it (no stroke, no refusal), sends it again after its resend
 * wait instead of waiting forever. The loss is real: a relay between the player and the server
 * drops the player's first shot message. Before the resend the player, and with it its room,
 * waited for good (the same state as a refused shot before RefusedShotTest's fix). The shot sent
 * again is played once: the stored strokes are the card's.
 */
class LostShotTest {
    @TempDir
    Path dir;

    @Test
    void aShotLostWithNoAnswerIsSentAgainAndTheRoundEnds() throws Exception {
        AtomicInteger shots = new AtomicInteger();
        try (GameServer server = TestServers.start(TestServers.options(dir.resolve("s.db").toString()), new StringWriter());
             LossyProxy proxy = new LossyProxy(server.port(), text -> isShot(text) && shots.getAndIncrement() == 0)) {
            List<String> out = Collections.synchronizedList(new ArrayList<>()), said = Collections.synchronizedList(new ArrayList<>());
            HeadlessPlayer player = new HeadlessPlayer(new HeadlessPlayer.Options(OnlineClient.uri("127.0.0.1:" + proxy.port()),
                    "flat", 1, List.of(), false, null, "Ann", "straight", null, 0), out::add, said::add, null)
                    .resendAfter(Duration.ofSeconds(2));
            JsonNode card = HeadlessRuns.playToTheEnd(player, out, said);
            assertEquals(1, proxy.lost(), "the first shot was lost on the way");
            assertTrue(shots.get() >= 2, "shots sent: " + shots.get());
            assertTrue(said.stream().anyMatch(l -> l.equals("no answer to the shot at event 0 for 2 s; sending it again")),
                    "said: " + said);
            HeadlessRuns.assertEveryStrokeStoredOnce(server, card);
        }
    }

    @Test
    void theResendWaitMustBePositive() {
        HeadlessPlayer player = new HeadlessPlayer(new HeadlessPlayer.Options(OnlineClient.uri("127.0.0.1:1"), "flat", 1, List.of(),
                false, null, "Ann", "straight", null, 0), line -> { }, line -> { }, null);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> player.resendAfter(Duration.ZERO));
        assertEquals("resend wait must be positive: PT0S", e.getMessage());
        assertEquals(Duration.ofSeconds(30), HeadlessPlayer.RESEND_AFTER, "longer than the slowest answer measured (25.3 s)");
    }

    private static boolean isShot(String text) {
        try {
            return "shot".equals(Json.parse(text).path("type").asText());
        } catch (ProtocolException e) {
            return false;
        }
    }
}
