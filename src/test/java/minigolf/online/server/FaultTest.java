package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.game.RoundGame;
import minigolf.online.ClientMessage;
import minigolf.online.Json;
import minigolf.online.RoomEvent;
import minigolf.online.client.OnlineClient;
import minigolf.online.store.GameStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The fault tests of docs/online.md: the server killed with kill -9 in the middle of a round and
 * started again on its database; a headless client killed in the middle of its round and started
 * again on its seat file; a client dropped between sending its shot and reading the outcome, beside
 * another room. Each ends with every score intact: the stored events are exactly the strokes the
 * players saw, each once.
 */
class FaultTest {
    @TempDir
    Path dir;

    @Test
    void theServerKilledMidRoundRestartsFromItsDatabaseWithEveryStroke() throws Exception {
        String db = dir.resolve("s.db").toString();
        Path err = dir.resolve("server.err");
        String code, annsToken, bobsToken;
        long seqBeforeKill;
        RoundGame beforeKill;
        try (Processes.Run server = Processes.start(err, "server", "--port", "0", "--db", db, "--host", "127.0.0.1")) {
            int port = Json.parse(server.nextLine(120)).get("port").asInt();
            try (TestClient ann = new TestClient(OnlineClient.uri("127.0.0.1:" + port));
                 TestClient bob = new TestClient(OnlineClient.uri("127.0.0.1:" + port))) {
                ann.send(new ClientMessage.Create("Ann", "meadowbrook-9", 2, List.of(), true, 10));
                code = ann.await("joined").get("room").asText();
                annsToken = ann.mirror.token();
                bob.send(new ClientMessage.Join(code, "Bob"));
                bob.await("joined");
                bobsToken = bob.mirror.token();
                ann.awaitState(() -> "playing".equals(ann.mirror.status()), "the start");
                bob.awaitState(() -> "playing".equals(bob.mirror.status()), "the start");
                for (int i = 0; i < 5; i++) {
                    TestClient next = ann.mirror.isMyTurn() ? ann : bob;
                    next.putt(0.8, 0.4);
                    TestClient other = next == ann ? bob : ann;
                    other.awaitState(() -> other.mirror.seq() == next.mirror.seq(), "the stroke");
                }
                seqBeforeKill = ann.mirror.seq();
                beforeKill = ann.mirror.round();
                // A shot on its way when the server dies: it is stored whole or not at all.
                TestClient next = ann.mirror.isMyTurn() ? ann : bob;
                next.send(new ClientMessage.Shot(next.mirror.seq(), 1.1, 0.2, 0, 0));
                server.kill9();
            }
        }
        try (Processes.Run server = Processes.start(err, "server", "--port", "0", "--db", db, "--host", "127.0.0.1")) {
            JsonNode started = Json.parse(server.nextLine(120));
            assertEquals(1, started.get("restoredRooms").asInt(), started.toString());
            int port = started.get("port").asInt();
            try (TestClient ann = new TestClient(OnlineClient.uri("127.0.0.1:" + port));
                 TestClient bob = new TestClient(OnlineClient.uri("127.0.0.1:" + port))) {
                ann.send(new ClientMessage.Resume(code, annsToken));
                ann.await("room");
                bob.send(new ClientMessage.Resume(code, bobsToken));
                bob.await("room");
                long seq = ann.mirror.seq();
                assertTrue(seq == seqBeforeKill || seq == seqBeforeKill + 1, "events " + seqBeforeKill + " or one more, got " + seq);
                RoundGame now = ann.mirror.round();
                for (int s = 0; s < 2; s++) {
                    if (seq == seqBeforeKill) {
                        assertEquals(beforeKill.game().player(s), now.game().player(s), "seat " + s + " as before the kill");
                    }
                }
                assertEquals(minigolf.game.SavedRounds.toJson(ann.mirror.round()), minigolf.game.SavedRounds.toJson(bob.mirror.round()));
                // Play on: the count continues from the stored events.
                TestClient next = ann.mirror.isMyTurn() ? ann : bob;
                assertEquals(seq + 1, next.putt(0.5, 0).get("seq").asLong());
            }
            server.kill9();
        }
        try (GameStore store = GameStore.open(db)) {
            List<String> events = store.events(code);
            for (int i = 0; i < events.size(); i++) {
                assertEquals(i + 1, RoomEvent.parse(Json.parse(events.get(i)), 2).seq(), "events are numbered 1, 2, 3, ... once each");
            }
        }
    }

    @Test
    void aClientKilledMidRoundResumesItsSeatAndTheRoundEndsWithEveryStroke() throws Exception {
        StringWriter log = new StringWriter();
        try (GameServer server = TestServers.start(TestServers.options(dir.resolve("s.db").toString()), log)) {
            String address = "127.0.0.1:" + server.port();
            Path err = dir.resolve("clients.err");
            Path annSeat = dir.resolve("ann.seat"), bobSeat = dir.resolve("bob.seat");
            try (Processes.Run ann = Processes.start(err, "join", address, "--create", "meadowbrook-9", "--seats", "2",
                    "--name", "Ann", "--bot", "straight", "--seat-file", annSeat.toString())) {
                String code = Json.parse(ann.nextLine(120)).get("room").asText();
                Room room = null;
                while (room == null) {
                    room = server.rooms().get(code);
                    Thread.sleep(20);
                }
                String card;
                try (Processes.Run bob = Processes.start(err, "join", address, "--room", code, "--name", "Bob", "--bot", "straight",
                        "--seat-file", bobSeat.toString())) {
                    // Kill Bob while the round is under way (after a few strokes, mid-hole or mid-stroke).
                    while (room.view().status().equals("lobby") || strokes(room.view()) < 6) Thread.sleep(5);
                    bob.kill9();
                }
                try (Processes.Run bobAgain = Processes.start(err, "join", address, "--room", code, "--name", "Bob",
                        "--bot", "straight", "--seat-file", bobSeat.toString())) {
                    card = bobAgain.nextLine(300);
                }
                String annsCard = ann.nextLine(300);
                JsonNode a = Json.parse(annsCard), b = Json.parse(card);
                assertEquals(a, b, "both clients end with the same card");
                assertEquals(2, a.get("players").size());
                assertEquals(9, a.get("players").get(1).get("strokes").size());
                // Every stroke stored once: the events, counted per seat and hole, give the card.
                List<RoomEvent> events = new ArrayList<>();
                for (String e : server.store().events(code)) events.add(RoomEvent.parse(Json.parse(e), 2));
                for (int i = 0; i < events.size(); i++) assertEquals(i + 1, events.get(i).seq());
                for (int s = 0; s < 2; s++) {
                    int[] perHole = new int[9];
                    for (RoomEvent e : events) {
                        if (e.seat() == s) perHole[e.hole()] = e.after().status() == minigolf.game.PlayerStatus.PICKED_UP
                                ? 11 : e.after().total();
                    }
                    for (int h = 0; h < 9; h++) {
                        assertEquals(a.get("players").get(s).get("strokes").get(h).asInt(), perHole[h], "seat " + s + " hole " + (h + 1));
                    }
                }
            }
        }
    }

    @Test
    void aClientDroppedMidStrokeResumesWithItsStrokeCountedOnceWhileAnotherRoomPlaysOn() throws Exception {
        try (GameServer server = TestServers.start(TestServers.options(dir.resolve("s.db").toString()), new StringWriter());
             TestClient ann = TestClient.to(server); TestClient bob = TestClient.to(server);
             TestClient carol = TestClient.to(server); TestClient dan = TestClient.to(server)) {
            String code = open(ann, bob), other = open(carol, dan);
            String bobsToken = bob.mirror.token();
            ann.putt(0.5, 0); // short: Bob, farther, plays next
            carol.putt(0.5, 0);
            bob.awaitMyTurn();
            long before = bob.mirror.seq();
            bob.send(new ClientMessage.Shot(before, 0.7, 0.1, 0, 0));
            // Bob's program dies between sending the shot and reading its outcome: the server has played and stored
            // it, Bob never takes the stroke in.
            while (server.store().events(code).size() < before + 1) Thread.sleep(2);
            bob.socket.abort();
            dan.putt(0.7, 0.1); // the other room plays on meanwhile
            try (TestClient back = TestClient.to(server)) {
                back.send(new ClientMessage.Resume(code, bobsToken));
                back.await("room");
                assertEquals(before + 1, back.mirror.seq(), "Bob's stroke was played, once");
                assertEquals(1, back.mirror.round().game().player(1).total());
                // Sent again after the crash (a client that did not see its outcome), the shot is stale: nothing twice.
                back.send(new ClientMessage.Shot(before, 0.7, 0.1, 0, 0));
                assertEquals("stale", back.await("error").get("code").asText());
                ann.awaitState(() -> ann.mirror.seq() == before + 1, "Bob's stroke at Ann");
                assertEquals(minigolf.game.SavedRounds.toJson(ann.mirror.round()), minigolf.game.SavedRounds.toJson(back.mirror.round()),
                        "Ann and the resumed Bob hold the same round");
                // The round goes on: the next stroke is numbered on from Bob's.
                TestClient next = TestClient.whoseTurn(ann, back);
                assertEquals(before + 2, next.putt(0.6, 0).get("seq").asLong());
            }
            assertEquals(List.of(1L, 2L, 3L), seqs(server, code));
            assertEquals(List.of(1L, 2L), seqs(server, other), "the other room's strokes, each once");
            carol.awaitState(() -> carol.mirror.seq() == 2, "Dan's stroke at Carol");
            assertEquals(minigolf.game.SavedRounds.toJson(carol.mirror.round()), minigolf.game.SavedRounds.toJson(dan.mirror.round()));
        }
    }

    /** A two-seat room on Flat, started (Ann-style creator, then the joiner). */
    private static String open(TestClient host, TestClient guest) throws InterruptedException {
        host.send(new ClientMessage.Create("Host", "flat", 2, List.of(), true, 10));
        String code = host.await("joined").get("room").asText();
        guest.send(new ClientMessage.Join(code, "Guest"));
        guest.await("joined");
        host.awaitState(() -> "playing".equals(host.mirror.status()), "the start");
        guest.awaitState(() -> "playing".equals(guest.mirror.status()), "the start");
        return code;
    }

    private static List<Long> seqs(GameServer server, String code) throws Exception {
        List<Long> out = new ArrayList<>();
        for (String e : server.store().events(code)) out.add(RoomEvent.parse(Json.parse(e), 2).seq());
        return out;
    }

    private static int strokes(RoomView v) {
        int n = 0;
        for (int s = 0; s < v.names().size(); s++) n += v.total(s);
        return n;
    }
}
