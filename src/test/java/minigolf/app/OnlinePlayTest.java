package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import minigolf.online.ClientMessage;
import minigolf.online.client.OnlineClient;
import minigolf.online.server.CourseCatalog;
import minigolf.online.server.GameServer;
import minigolf.online.server.LossyProxy;
import minigolf.online.server.ServerOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The game's side of an online room without a window: what it says when the server is unreachable or a player leaves. */
class OnlinePlayTest {
    @TempDir
    Path dir;

    private static void until(OnlinePlay p, BooleanSupplier done, String what) throws InterruptedException {
        for (int i = 0; i < 600 && !done.getAsBoolean(); i++) {
            p.poll();
            Thread.sleep(50);
        }
        assertTrue(done.getAsBoolean(), what);
    }

    @Test
    void anUnreachableServerIsSaidInOneLine() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort(); // free once closed: nobody listens there
        }
        List<String> said = new ArrayList<>();
        OnlinePlay p = new OnlinePlay(new OnlinePlay.Entry(OnlineClient.uri("127.0.0.1:" + port), "Ann", "flat", 2, List.of(),
                true, null, null), said::add, (room, token) -> { });
        until(p, () -> p.failure() != null, "a failure");
        assertTrue(p.failure().startsWith("cannot reach the server at 127.0.0.1:" + port), p.failure());
        assertTrue(!p.failure().contains("\n"));
        assertTrue(said.contains(p.failure()), said.toString());
    }

    @Test
    void aPlayerWhoLeavesIsSaidAndTheRoomsCodeAndTokenAreReported() throws Exception {
        Path courses = Path.of(System.getProperty("minigolf.projectDir", "."), "courses");
        ServerOptions o = ServerOptions.defaults(0, dir.resolve("s.db").toString(), courses).withHost("127.0.0.1");
        try (GameServer server = GameServer.start(o, CourseCatalog.load(courses, new PrintWriter(new StringWriter())),
                new PrintWriter(new StringWriter(), true))) {
            List<String> said = new ArrayList<>();
            String[] seat = new String[2];
            OnlinePlay ann = new OnlinePlay(new OnlinePlay.Entry(OnlineClient.uri("127.0.0.1:" + server.port()), "Ann", "flat", 2,
                    List.of(), true, null, null), said::add, (room, token) -> {
                        seat[0] = room;
                        seat[1] = token;
                    });
            until(ann, () -> seat[0] != null, "the room's code");
            assertTrue(minigolf.online.Protocol.TOKEN.matcher(seat[1]).matches());
            StringBuilder bobSays = new StringBuilder();
            OnlineClient bob = OnlineClient.connect(OnlineClient.uri("127.0.0.1:" + server.port()), new OnlineClient.Listener() {
                public void onMessage(com.fasterxml.jackson.databind.node.ObjectNode m) {
                    synchronized (bobSays) {
                        bobSays.append(m.path("type").asText()).append(' ');
                    }
                }

                public void onClosed(String reason) {
                }
            }, java.time.Duration.ofSeconds(10));
            bob.send(new ClientMessage.Join(seat[0], "Bob"));
            until(ann, () -> ann.shown() != null, "the round starts");
            assertEquals(0, ann.mirror().seat());
            assertTrue(ann.canShoot(), "Ann (seat 0) tees off");
            bob.send(new ClientMessage.Leave());
            until(ann, () -> ann.chat().stream().anyMatch(l -> l.equals("Bob left the game")), "the leave said");
            assertTrue(said.contains("Bob left the game"), said.toString());
            // The server sends the seats after the notice: under load they may come a moment later.
            until(ann, () -> ann.mirror().seats().size() > 1 && ann.mirror().seats().get(1).gone(), "Bob's seat marked gone");
            assertNotNull(ann.mirror().seats().get(1));
            assertTrue(ann.mirror().seats().get(1).gone());
            bob.close();
            ann.close();
        }
    }

    /**
     * The window's side of a shot lost on its way (a relay drops it: no stroke, no refusal comes): before,
     * the seat kept its turn and could never shoot again. After the answer wait the shot may be played
     * again, the player is told, and the stroke is played.
     */
    @Test
    void aShotLostOnItsWayMayBePlayedAgainAfterTheWait() throws Exception {
        Path courses = Path.of(System.getProperty("minigolf.projectDir", "."), "courses");
        ServerOptions o = ServerOptions.defaults(0, dir.resolve("s.db").toString(), courses).withHost("127.0.0.1");
        java.util.concurrent.atomic.AtomicInteger shots = new java.util.concurrent.atomic.AtomicInteger();
        try (GameServer server = GameServer.start(o, CourseCatalog.load(courses, new PrintWriter(new StringWriter())),
                new PrintWriter(new StringWriter(), true));
             LossyProxy proxy = new LossyProxy(server.port(), text -> LossyProxy.isType(text, "shot") && shots.getAndIncrement() == 0)) {
            List<String> said = new ArrayList<>();
            OnlinePlay ann = new OnlinePlay(new OnlinePlay.Entry(OnlineClient.uri("127.0.0.1:" + proxy.port()), "Ann", "flat", 1,
                    List.of(), true, null, null), said::add, (room, token) -> { });
            ann.answerWait(java.time.Duration.ofSeconds(2));
            until(ann, () -> ann.shown() != null && ann.canShoot(), "Ann's turn");
            ann.shoot(1, 0, 0);
            assertFalse(ann.canShoot(), "the shot is on its way");
            until(ann, ann::canShoot, "the shot may be played again");
            assertEquals(1, proxy.lost());
            assertTrue(said.contains("no answer from the server to the shot for 2 s: play it again"), said.toString());
            assertEquals(0, ann.mirror().seq(), "no stroke was played");
            ann.shoot(1, 0, 0);
            until(ann, () -> ann.mirror().seq() == 1, "the stroke");
            assertEquals(1, ann.mirror().round().game().player(0).strokes(), "one stroke on the server's count");
            assertEquals(2, shots.get(), "two shots sent, the first lost");
            ann.close();
        }
    }
}
