package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
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

import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;

/**
 * An online stroke still waiting out its wait (a client may send one, e.g. {@code join --bot} on a
 * course with moving obstacles) is dropped when play ends: a hot-seat game started next must not
 * animate it (it did, on the new game's ball, and the stroke's end then threw "no stroke is rolling").
 * Checked on the play session alone and in the game window.
 */
class HeldOnlineStrokeTest {
    @TempDir
    Path dir;
    private Path windmill;

    private static void until(PlaySession s, BooleanSupplier done, String what) throws InterruptedException {
        for (int i = 0; i < 600 && !done.getAsBoolean(); i++) {
            s.advance(1.0, 1, false); // a whole second a pass: strokes without a wait end at once
            Thread.sleep(50);
        }
        assertTrue(done.getAsBoolean(), what);
    }

    /** A server offering the windmill (moving obstacles: a stroke may wait for its moment); {@link #windmill} is its file. */
    private GameServer windmillServer() throws Exception {
        Path courses = Files.createDirectories(dir.resolve("courses"));
        Path source = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "practice", "windmill.json");
        windmill = Files.copy(source, courses.resolve("windmill.json"));
        ServerOptions o = ServerOptions.defaults(0, dir.resolve("s.db").toString(), courses).withHost("127.0.0.1");
        return GameServer.start(o, CourseCatalog.load(courses, new PrintWriter(new StringWriter())),
                new PrintWriter(new StringWriter(), true));
    }

    /** Bob, a bare protocol client, takes the room's second seat; he shoots only when told. */
    private static OnlineClient bob(GameServer server, String room) throws Exception {
        OnlineClient bob = OnlineClient.connect(OnlineClient.uri("127.0.0.1:" + server.port()), new OnlineClient.Listener() {
            public void onMessage(com.fasterxml.jackson.databind.node.ObjectNode m) {
            }

            public void onClosed(String reason) {
            }
        }, java.time.Duration.ofSeconds(10));
        bob.send(new ClientMessage.Join(room, "Bob"));
        return bob;
    }

    @Test
    void aHeldOnlineStrokeIsNotPlayedOnTheNextHotSeatGame() throws Exception {
        try (GameServer server = windmillServer()) {
            List<String> said = new ArrayList<>();
            PlaySession session = new PlaySession(World.load(windmill), windmill, List.of(),
                    new PlayerFiles(new SettingsStore(dir.resolve("config")), said::add), said::add);
            String[] room = new String[1];
            OnlinePlay ann = new OnlinePlay(new OnlinePlay.Entry(OnlineClient.uri("127.0.0.1:" + server.port()), "Ann", "windmill", 2,
                    List.of(), false, null, null), said::add, (code, token) -> room[0] = code);
            session.startOnline(ann);
            until(session, () -> room[0] != null, "the room's code");
            OnlineClient bob = bob(server, room[0]);
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

    /**
     * The same in the game window (a real server, Ann's scripted stroke, then Bob's with a 30 s wait):
     * the held stroke is taken in, the player leaves for the main menu and starts a hot-seat game;
     * SPACE there starts nothing, the new game's first stroke is its own, and no frame throws.
     */
    @Test
    @minigolf.render.NeedsDisplay
    void inTheWindowTooTheHeldStrokeIsDroppedWhenPlayEnds() throws Exception {
        try (GameServer server = windmillServer()) {
            GameApp app = new GameApp(World.load(windmill), new GameApp.Options(windmill, null, 3000, null,
                    List.of(new double[]{0.4, 0}), 1, new SettingsStore(dir.resolve("config")), true, false));
            String[] room = new String[1];
            app.playOnline(OnlineClient.uri("127.0.0.1:" + server.port()), "Ann", "windmill", 2, List.of(), null,
                    code -> room[0] = code);
            OnlineClient[] bob = new OnlineClient[1];
            int[] step = {0};
            boolean[] held = {false}, spaceStartedNothing = {false};
            app.onLoopPass((pass, w) -> {
                try {
                    OnlinePlay on = app.play().online();
                    if (step[0] == 0 && room[0] != null) {
                        bob[0] = bob(server, room[0]);
                        step[0] = 1;
                    } else if (step[0] == 1 && on != null && on.mirror().seq() > 0 && on.mirror().seat() == 0
                            && !on.mirror().isMyTurn() && app.play().animator() == null) {
                        // Ann's scripted stroke is shown; Bob's waits 30 s on the room's clock.
                        bob[0].send(new ClientMessage.Shot(on.mirror().seq(), 0.4, 0, 0, 30));
                        step[0] = 2;
                    } else if (step[0] == 2 && app.play().onlineStrokeWaiting()) {
                        held[0] = true;
                        app.toMainMenu();
                        app.startGame(List.of(Player.human("Ann"), Player.human("Bob")));
                        app.screen().keyPressed(GLFW_KEY_SPACE, 0);
                        spaceStartedNothing[0] = app.play().animator() == null;
                        app.play().hit(0.4, 0, 0);
                        step[0] = 3;
                    } else if (step[0] == 3 && app.play().animator() == null) {
                        step[0] = 4;
                        w.requestClose();
                    }
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            app.run();
            assertTrue(held[0], "Bob's stroke was taken in and held in the window");
            assertTrue(spaceStartedNothing[0], "SPACE in the new game animates nothing");
            assertEquals(4, step[0], "the new game's own stroke ended");
            assertEquals(1, app.game().player(0).total(), "Ann's stroke counted in the new game");
            assertEquals(0, app.game().player(1).total(), "Bob has not played in the new game");
            if (bob[0] != null) bob[0].close();
        }
    }
}
