package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicReference;
import minigolf.online.ClientMessage;
import minigolf.online.Json;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * 10,000 malformed, oversized and out-of-turn messages from a seated player and two strangers while
 * another room plays a whole round: every one is answered with an error and dropped, the flooded
 * room's balls and counts do not move, it plays on normally afterwards, and the other room ends
 * with a card that matches its stored strokes.
 */
class FloodTest {
    static final int MESSAGES = 10_000;

    @TempDir
    Path dir;

    /** The kinds of bad message, each with the error code the server answers. */
    private static String[] bad(int i, String room, long seq) {
        return switch (i % 14) {
            case 0 -> new String[]{"{not json", "bad-message"};
            case 1 -> new String[]{"{\"type\":\"teleport\",\"to\":[3,0.5]}", "bad-message"};
            case 2 -> new String[]{"{\"type\":\"shot\",\"seq\":\"0\",\"velocity\":[1,0]}", "bad-field"};
            case 3 -> new String[]{"{\"type\":\"chat\",\"text\":\"" + "x".repeat(5000) + "\"}", "too-large"};
            case 4 -> new String[]{"{\"type\":\"shot\",\"seq\":" + seq + ",\"velocity\":[1,0]}", "not-your-turn"};
            case 5 -> new String[]{"{\"type\":\"shot\",\"seq\":" + (seq + 7) + ",\"velocity\":[1,0]}", "stale"};
            case 6 -> new String[]{"{\"type\":\"shot\",\"seq\":" + seq + ",\"velocity\":[1e308,1e308]}", "not-your-turn"};
            case 7 -> new String[]{"{\"type\":\"shot\",\"seq\":" + seq + ",\"velocity\":[1,0],\"loft\":1e9}", "bad-field"};
            case 8 -> new String[]{"{\"type\":\"resume\",\"protocol\":1,\"room\":\"" + room + "\",\"token\":\"AAAAAAAAAAAAAAAAAAAAAA\"}",
                    "already-seated"};
            case 9 -> new String[]{"{\"type\":\"join\",\"protocol\":1,\"room\":\"ZZZZZZZZ\",\"name\":\"M\"}", "already-seated"};
            case 10 -> new String[]{"{\"type\":\"ping\",\"a\":" + "[".repeat(200) + "]".repeat(200) + "}", "bad-message"};
            case 11 -> new String[]{"{\"type\":\"create\",\"protocol\":1,\"name\":\"M\",\"course\":\"../../etc/passwd\",\"seats\":1}",
                    "bad-field"};
            case 12 -> new String[]{"{\"type\":\"chat\",\"text\":\"" + "y".repeat(201) + "\"}", "bad-field"};
            default -> new String[]{"{\"type\":\"shot\",\"seq\":" + seq + ",\"velocity\":[1,0],\"extra\":true}", "bad-field"};
        };
    }

    /** What a stranger (no seat) gets for the same messages: a room message without a seat is not-seated. */
    private static String strangerCode(String[] m) {
        return switch (m[1]) {
            case "not-your-turn", "stale" -> "not-seated";
            default -> m[1];
        };
    }

    /**
     * A stranger's join or resume is refused with no-room or bad-token, or with already-seated while
     * the previous one is still being answered (one seat claim at a time): counted together.
     */
    private static String seatCodes(String code) {
        return switch (code) {
            case "bad-token", "no-room", "already-seated" -> "seat refused";
            default -> code;
        };
    }

    @Test
    void tenThousandBadMessagesChangeNothingAndTheOtherRoomPlaysOn() throws Exception {
        ServerOptions o = TestServers.options(dir.resolve("s.db").toString()).withRate(100_000, 100_000);
        try (GameServer server = TestServers.start(o, new StringWriter());
             TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server); TestClient mallory = TestClient.to(server);
             TestClient s1 = TestClient.to(server); TestClient s2 = TestClient.to(server)) {
            // The other room: Carol (a headless bot client) and a server bot play the front nine meanwhile.
            AtomicReference<String> carolsCard = new AtomicReference<>();
            AtomicReference<Throwable> carolFailed = new AtomicReference<>();
            Thread carol = new Thread(() -> {
                try {
                    new HeadlessPlayer(new HeadlessPlayer.Options(OnlineClient.uri("127.0.0.1:" + server.port()), "meadowbrook-9",
                            2, List.of("straight"), true, null, "Carol", "straight", null, 0), carolsCard::set, line -> { }, null).run();
                } catch (Throwable t) {
                    carolFailed.set(t);
                }
            });
            carol.start();

            ann.send(new ClientMessage.Create("Ann", "flat", 3, List.of(), true, 10));
            String room = ann.await("joined").get("room").asText();
            bob.send(new ClientMessage.Join(room, "Bob"));
            bob.await("joined");
            mallory.send(new ClientMessage.Join(room, "Mallory"));
            mallory.await("joined");
            ann.awaitState(() -> "playing".equals(ann.mirror.status()), "the start");
            mallory.awaitState(() -> "playing".equals(mallory.mirror.status()), "the start");
            String before = minigolf.game.SavedRounds.toJson(ann.mirror.round());

            Map<String, Integer> expected = new TreeMap<>(), answered = new TreeMap<>();
            TestClient[] senders = {mallory, s1, s2};
            int sent = 0;
            for (int batch = 0; sent < MESSAGES; batch++) {
                TestClient c = senders[batch % 3];
                int n = Math.min(100, MESSAGES - sent);
                for (int i = 0; i < n; i++) {
                    String[] m = bad(sent + i, room, 0);
                    expected.merge(seatCodes(c == mallory ? m[1] : strangerCode(m)), 1, Integer::sum);
                    c.socket.sendText(m[0]);
                }
                for (int i = 0; i < n; i++) {
                    JsonNode e = c.await(x -> x.path("type").asText().equals("error"), "error reply " + i + " of batch " + batch);
                    answered.merge(seatCodes(e.get("code").asText()), 1, Integer::sum);
                }
                sent += n;
            }
            assertEquals(expected, answered, "every bad message answered with its error");
            assertEquals(MESSAGES, answered.values().stream().mapToInt(Integer::intValue).sum());

            // Nothing moved in the flooded room; it plays on as usual.
            ann.drain();
            assertEquals(0, ann.mirror.seq());
            assertEquals(before, minigolf.game.SavedRounds.toJson(ann.mirror.round()));
            assertEquals(1, ann.putt(1, 0).get("seq").asLong());

            // A frame beyond 64 KB is not even read: that connection is closed; the server goes on.
            s1.socket.sendText("{\"type\":\"chat\",\"text\":\"" + "z".repeat(70_000) + "\"}");
            for (int i = 0; i < 100 && s1.closedReason == null; i++) Thread.sleep(50);
            assertNotNull(s1.closedReason, "the oversized frame closes its connection");
            assertTrue(s1.closedReason.contains("1009"), s1.closedReason);
            bob.awaitMyTurn();
            assertEquals(2, bob.putt(1, 0.05).get("seq").asLong());

            carol.join(300_000);
            assertEquals(null, carolFailed.get());
            JsonNode card = Json.parse(carolsCard.get());
            assertEquals(9, card.get("players").get(0).get("strokes").size());
            assertEquals(9, card.get("players").get(1).get("strokes").size());
            String carolsRoom = card.get("room").asText();
            int stored = server.store().events(carolsRoom).size();
            int hits = 0;
            for (JsonNode p : card.get("players")) for (JsonNode h : p.get("strokes")) hits += Math.min(h.asInt(), 10);
            assertTrue(stored <= hits && stored > 0, stored + " stored events for " + hits + " strokes on the card");
        }
    }
}
