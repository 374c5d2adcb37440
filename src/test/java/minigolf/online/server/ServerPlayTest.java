package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.PlayerStatus;
import minigolf.game.RoundGame;
import minigolf.online.ClientMessage;
import minigolf.online.Protocol;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Two clients in one room through a real server: seats, turns, the checks on every shot, and the server's physics. */
class ServerPlayTest {
    @TempDir
    Path dir;

    /** On Flat (friction 0.1, start at (-3, 0)) a 1 m/s putt along x stops after v^2 / (2 mu g) = 0.5097 m. */
    static final double ONE_METRE_PER_SECOND_ROLL = 1.0 / (2 * 0.1 * 9.81);

    /** Where seat {@code seat}'s ball waits beside the flat course's tee (-3, 0) in a two-player room (TeeSpots). */
    static minigolf.course.Vec2 tee(int seat) {
        return minigolf.game.TeeSpots.of(minigolf.app.GameLauncher.loadBundled("/courses/flat.json"), 2).get(seat);
    }

    @Test
    void twoPlayersTakeTurnsAndEveryShotIsChecked() throws Exception {
        try (GameServer server = TestServers.start(dir.resolve("s.db").toString());
             TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "flat", 2, List.of(), true, 10));
            ObjectNode joined = ann.await("joined");
            String code = joined.get("room").asText();
            assertTrue(Protocol.CODE.matcher(code).matches(), code);
            assertTrue(Protocol.TOKEN.matcher(joined.get("token").asText()).matches());
            assertEquals("lobby", ann.await("room").get("status").asText());

            bob.send(new ClientMessage.Join(code, "Ann")); // the name is taken: Bob becomes "Ann 2"
            assertEquals("Ann 2", bob.await("joined").get("name").asText());
            assertEquals("playing", bob.await(m -> m.path("type").asText().equals("room")
                    && m.path("status").asText().equals("playing"), "the start").get("status").asText());
            ann.await(m -> "playing".equals(ann.mirror.status()), "the start");

            // Bob (seat 1) may not play first; a shot with an old count, or faster than the course allows, is refused.
            bob.send(new ClientMessage.Shot(0, 1, 0, 0, 0));
            assertEquals("not-your-turn", bob.await("error").get("code").asText());
            ann.send(new ClientMessage.Shot(5, 1, 0, 0, 0));
            assertEquals("stale", ann.await("error").get("code").asText());
            ann.send(new ClientMessage.Shot(0, 4.01, 0, 0, 0));
            ObjectNode tooFast = ann.await("error");
            assertEquals("bad-field", tooFast.get("code").asText());
            assertTrue(tooFast.get("message").asText().contains("maxSpeed"), tooFast.toString());

            ObjectNode stroke = ann.putt(1, 0);
            assertEquals(1, stroke.get("seq").asLong());
            assertEquals(0, stroke.get("seat").asInt());
            assertEquals("stopped", stroke.get("outcome").asText());
            assertEquals(tee(0).x() + ONE_METRE_PER_SECOND_ROLL, stroke.get("end").get(0).asDouble(), 1e-3);
            assertEquals(tee(0).y(), stroke.get("end").get(1).asDouble(), 1e-9);
            // Bob is now farthest from the hole: his turn; both clients settle the stroke where the server put it.
            bob.await(m -> m.path("seq").asLong() == 1 && m.path("type").asText().equals("stroke"), "stroke 1");
            assertEquals(1, stroke.get("turn").asInt());
            for (TestClient c : List.of(ann, bob)) {
                RoundGame r = c.mirror.round();
                assertEquals(stroke.get("end").get(0).asDouble(), r.game().player(0).x(), 0);
                assertEquals(1, r.game().player(0).strokes());
                assertEquals(1, c.mirror.seq());
            }
            // The same shot again (same count) is a duplicate: refused, counted once.
            ann.send(new ClientMessage.Shot(0, 1, 0, 0, 0));
            assertEquals("stale", ann.await("error").get("code").asText());

            ObjectNode bobs = bob.putt(2, 0.3);
            assertEquals(2, bobs.get("seq").asLong());
            bob.send(new ClientMessage.Chat("nice <b>shot</b>"));
            ObjectNode chat = ann.await("chat");
            assertEquals("Ann 2", chat.get("name").asText());
            assertEquals("nice <b>shot</b>", chat.get("text").asText());
            assertFalse(ann.mirror.round().isOver());
        }
    }

    @Test
    void aRoundWithAServerBotPlaysToTheEndAndFillsTheLeaderboards() throws Exception {
        try (GameServer server = TestServers.start(dir.resolve("s.db").toString()); TestClient ann = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "flat", 2, List.of("straight"), true, 3));
            ann.await(m -> "playing".equals(ann.mirror.status()), "the start");
            // Ann putts softly until she picks up at the limit of 3; the bot plays its straight putts meanwhile.
            while (!ann.mirror.round().isOver()) {
                if (ann.mirror.isMyTurn()) ann.putt(0.5, 0);
                else ann.await(m -> ann.mirror.isMyTurn() || ann.mirror.round().isOver(), "a turn or the end");
            }
            RoundGame r = ann.mirror.round();
            assertEquals(4, r.scorecard().rows().get(0).holes()[0], "picked up at the limit of 3: scores 4");
            ObjectNode end = ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("finished"),
                    "the finished room");
            assertNotNull(end.get("start"));
            assertEquals(end.get("seq").asLong(), end.get("events").size(), "the finished room holds every event");
            String board = new String(new java.net.URL("http://127.0.0.1:" + server.port() + "/api/course/flat").openStream()
                    .readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            assertTrue(board.contains("\"name\":\"Ann\",\"strokes\":4"), board);
            assertTrue(board.contains("\"bot\":\"straight\""), board);
            assertEquals(PlayerStatus.PICKED_UP, PlayerStatus.fromJsonName("picked-up"));
        }
    }
}
