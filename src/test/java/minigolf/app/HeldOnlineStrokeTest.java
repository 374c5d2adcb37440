package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.online.ClientMessage;
import minigolf.online.client.OnlineClient;
import minigolf.online.server.CourseCatalog;
import minigolf.online.server.GameServer;
import minigolf.online.server.ServerOptions;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An online stroke still waiting out its wait (a client may send one, e.g. {@code join --bot} on a
 * course with moving obstacles) is dropped when play ends: a hot-seat game started next must not
 * animate it (it did, on the new game's ball, and the stroke's end then threw "no stroke is rolling").
 */
class HeldOnlineStrokeTest {
    @TempDir
    Path dir;

    private static void until(PlaySession s, BooleanSupplier done, String what) throws InterruptedException {
        for (int i = 0; i < 600 && !done.getAsBoolean(); i++) {
            s.advance(1.0, 1, false); // a whole second a pass: strokes without a wait end at once
            Thread.sleep(50);
        }
        assertTrue(done.getAsBoolean(), what);
    }

    @Test
    void aHeldOnlineStrokeIsNotPlayedOnTheNextHotSeatGame() throws Exception {
        Path courses = Files.createDirectories(dir.resolve("courses"));
        Path source = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "practice", "windmill.json");
        Path windmill = Files.copy(source, courses.resolve("windmill.json"));
        ServerOptions o = ServerOptions.defaults(0, dir.resolve("s.db").toString(), courses).withHost("127.0.0.1");
        try (GameServer server = GameServer.start(o, CourseCatalog.load(courses, new PrintWriter(new StringWriter())),
                new PrintWriter(new StringWriter(), true))) {
            List<String> said = new ArrayList<>();
            PlaySession session = new PlaySession(World.load(windmill), windmill, List.of(),
                    new PlayerFiles(new SettingsStore(dir.resolve("config")), said::add), said::add);
            String[] room = new String[1];
            OnlinePlay ann = new OnlinePlay(new OnlinePlay.Entry(OnlineClient.uri("127.0.0.1:" + server.port()), "Ann", "windmill", 2,
                    List.of(), false, null, null), said::add, (code, token) -> room[0] = code);
            session.startOnline(ann);
            until(session, () -> room[0] != null, "the room's code");
            OnlineClient bob = OnlineClient.connect(OnlineClient.uri("127.0.0.1:" + server.port()), new OnlineClient.Listener() {
                public void onMessage(com.fasterxml.jackson.databind.node.ObjectNode m) {
                }

                public void onClosed(String reason) {
                }
            }, java.time.Duration.ofSeconds(10));
            bob.send(new ClientMessage.Join(room[0], "Bob"));
            until(session, ann::canShoot, "Ann tees off");
            ann.shoot(0.4, 0, 0);
            until(session, () -> ann.mirror().seq() > 0 && ann.mirror().seat() == 0 && !ann.mirror().isMyTurn()
                    && session.animator() == null, "Ann's stroke shown, Bob to play");
            // Bob's shot waits 5 s on the room's clock before the ball is hit; no time passes for Ann's view.
            long seq = ann.mirror().seq();
            bob.send(new ClientMessage.Shot(seq, 0.4, 0, 0, 5));
            for (int i = 0; i < 600 && ann.mirror().seq() == seq; i++) {
                session.advance(0, 1, false);
                Thread.sleep(50);
            }
            for (int i = 0; i < 5; i++) session.advance(0, 1, false); // the stroke is taken in and held
            assertTrue(session.onlineStrokeWaiting(), "Bob's stroke taken in and held");
            assertNull(session.animator(), "held, not rolling yet");

            session.end();
            session.start(List.of(Player.human("Ann"), Player.human("Bob")), UserSettings.DEFAULTS);
            session.skipAnimation();
            assertNull(session.animator(), "SPACE in the new game animates nothing");
            session.hit(0.4, 0, 0);
            assertNotNull(session.animator(), "the new game plays its own first stroke");
            until(session, () -> session.animator() == null, "the new game's stroke ends");
            assertTrue(session.game().player(0).total() == 1, "Ann's stroke counted in the new game");
            bob.close();
        }
    }
}
