package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import minigolf.online.ClientMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A player whose connection drops: the others are told, the dropped turn is passed over after the
 * away timeout, the dropped player picks up when only they are left, and a player who comes back
 * with the seat's token resumes where the ball lies.
 */
class DroppedPlayerTest {
    @TempDir
    Path dir;

    private GameServer server(double away, double pickup) throws Exception {
        return TestServers.start(TestServers.options(dir.resolve("s.db").toString()).withTimeouts(away, pickup), new StringWriter());
    }

    private static String open(TestClient ann, TestClient bob, int strokeLimit) throws InterruptedException {
        ann.send(new ClientMessage.Create("Ann", "flat", 2, List.of(), true, strokeLimit));
        String code = ann.await("joined").get("room").asText();
        bob.send(new ClientMessage.Join(code, "Bob"));
        bob.await("joined");
        ann.awaitState(() -> "playing".equals(ann.mirror.status()), "the start");
        bob.awaitState(() -> "playing".equals(bob.mirror.status()), "the start");
        return code;
    }

    @Test
    void aDroppedTurnIsPassedOverAndTheDroppedPlayerPicksUpWhenAloneOnTheHole() throws Exception {
        try (GameServer server = server(0.3, 0.6); TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server)) {
            open(ann, bob, 2);
            ann.putt(0.5, 0); // Ann is short: Bob (farther) to play
            bob.awaitMyTurn();
            bob.socket.abort();
            assertTrue(ann.await("notice").get("text").asText().contains("Bob lost the connection"));
            // After the away timeout Bob is passed over: the turn is Ann's although Bob is farther.
            ann.await(m -> m.path("type").asText().equals("seats") && m.path("seats").get(1).path("passedOver").asBoolean(),
                    "Bob passed over");
            assertEquals(0, ann.mirror.turn());
            ann.putt(0.5, 0); // Ann's second stroke: she reaches the limit of 2 and picks up
            // Only Bob is left, away: after the pick-up timeout he picks up, and the hole (the round) is over.
            ObjectNode pickup = ann.await("pickup");
            assertEquals(1, pickup.get("seat").asInt());
            assertEquals("picked-up", pickup.get("status").asText());
            assertEquals(0, pickup.get("strokes").asInt());
            ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("finished"), "the end");
            assertEquals(3, ann.mirror.round().scorecard().rows().get(0).total(), "Ann picked up at 2: scores 3");
            assertEquals(3, ann.mirror.round().scorecard().rows().get(1).total(), "Bob picked up without a stroke: scores 3");
        }
    }

    @Test
    void aPlayerWhoComesBackResumesTheSeatAndTheTurn() throws Exception {
        try (GameServer server = server(30, 60); TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server)) {
            String code = open(ann, bob, 10);
            String bobsToken = bob.mirror.token();
            ann.putt(0.5, 0);
            bob.socket.abort();
            ann.await("notice");
            try (TestClient back = TestClient.to(server)) {
                back.send(new ClientMessage.Resume(code, "A".repeat(22)));
                assertEquals("bad-token", back.await("error").get("code").asText());
                back.send(new ClientMessage.Resume(code, bobsToken));
                assertEquals(1, back.await("joined").get("seat").asInt());
                back.await("room");
                assertEquals(1, back.mirror.seq());
                assertTrue(back.mirror.isMyTurn(), "Bob's turn is waiting for him");
                assertTrue(ann.await("notice").get("text").asText().contains("Bob is back"));
                ObjectNode s = back.putt(1, 0);
                assertEquals(2, s.get("seq").asLong());
                assertEquals(ServerPlayTest.tee(1).x() + ServerPlayTest.ONE_METRE_PER_SECOND_ROLL, s.get("end").get(0).asDouble(),
                        1e-3);
            }
        }
    }

    @Test
    void aServerRestartRestoresTheRoomFromItsDatabase() throws Exception {
        restartRestoresTheRoom(dir.resolve("s.db").toString(), 1);
    }

    /** Two strokes, a server stopped and started on the same database, then the game goes on ({@code rooms} restored). */
    static void restartRestoresTheRoom(String db, int rooms) throws Exception {
        String code, annsToken, bobsToken;
        double annX, bobX;
        try (GameServer server = TestServers.start(db); TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server)) {
            code = open(ann, bob, 10);
            annsToken = ann.mirror.token();
            bobsToken = bob.mirror.token();
            ann.putt(0.5, 0);
            bob.putt(0.7, 0.1);
            bob.awaitState(() -> bob.mirror.seq() == 2, "both strokes");
            ann.awaitState(() -> ann.mirror.seq() == 2, "both strokes");
            annX = ann.mirror.round().game().player(0).x();
            bobX = ann.mirror.round().game().player(1).x();
        }
        try (GameServer again = TestServers.start(db); TestClient ann = TestClient.to(again); TestClient bob = TestClient.to(again)) {
            assertTrue(again.restoredRooms() >= rooms, "restored " + again.restoredRooms());
            ann.send(new ClientMessage.Resume(code, annsToken));
            ann.await("room");
            assertEquals(2, ann.mirror.seq());
            assertEquals(annX, ann.mirror.round().game().player(0).x(), 0);
            assertEquals(bobX, ann.mirror.round().game().player(1).x(), 0);
            assertEquals(1, ann.mirror.round().game().player(1).strokes());
            bob.send(new ClientMessage.Resume(code, bobsToken));
            bob.await("room");
            TestClient next = ann.mirror.isMyTurn() ? ann : bob;
            ObjectNode s = next.putt(0.4, 0);
            assertEquals(3, s.get("seq").asLong(), "the count goes on from the stored events");
        }
    }
}
