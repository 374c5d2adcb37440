package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.SettingsStore;
import minigolf.online.Json;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import minigolf.online.server.CourseCatalog;
import minigolf.online.server.GameServer;
import minigolf.online.server.ServerOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;

/**
 * The game window in an online room under Xvfb: Ann hosts a room on Flat from the window, a headless
 * bot client joins with the code, Ann's scripted ace goes to the server, the bot's strokes come back
 * and are animated; the window shows the same round card the other client printed, and its "Play
 * again" (clicked) opens Play online, after "Watch hole 1 again" has replayed every stroke where the
 * server ended it; the seat is remembered for a resume, and the online round saves and loads back as
 * a hot-seat round does.
 */
@minigolf.render.NeedsDisplay
class OnlineWindowTest {
    @TempDir
    Path dir;

    @Test
    void aHoleAgainstAHeadlessClientThroughARealServer() throws Exception {
        Path courses = Path.of(System.getProperty("minigolf.projectDir", "."), "courses");
        ServerOptions o = ServerOptions.defaults(0, dir.resolve("s.db").toString(), courses).withHost("127.0.0.1");
        try (GameServer server = GameServer.start(o, CourseCatalog.load(courses, new PrintWriter(new StringWriter())),
                new PrintWriter(new StringWriter(), true))) {
            Path config = dir.resolve("config");
            GameApp app = new GameApp(GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE), new GameApp.Options(null, null, 6000,
                    null, List.of(new double[]{3.425, 0.2854}), 20, new SettingsStore(config), true, false));
            AtomicReference<String> bobsCard = new AtomicReference<>();
            AtomicReference<Throwable> bobFailed = new AtomicReference<>();
            boolean[] sawLobby = {false}, sawPlay = {false}, sawReplay = {false};
            int[] finalCardPasses = {0};
            app.onLoopPass((pass, w) -> {
                sawLobby[0] |= app.screen() == app.screens().lobby();
                sawPlay[0] |= app.screen() == app.screens().playing();
                sawReplay[0] |= app.screen() == app.screens().replay();
                if (app.screen() != app.screens().roundCard() || app.roundGame() == null || !app.roundGame().isOver()) return;
                // The final card, drawn a few times (a new panel takes its size in its second frame): its "Watch
                // hole 1 again" (the button's action), back on the card when the replay is over, then a click on
                // its "Play again", as the pointer would make it.
                if (++finalCardPasses[0] == 3) app.watchReplay();
                if (finalCardPasses[0] == 8) {
                    float[] r = app.screens().roundCard().playAgainBounds();
                    app.uiLayer().mouseMove(r[0] + r[2] / 2, r[1] + r[3] / 2);
                    app.uiLayer().mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
                    app.uiLayer().mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
                }
                if (finalCardPasses[0] > 60) w.requestClose(); // the click did nothing
            });
            app.finishWhen(() -> app.screen() == app.screens().online());
            app.playOnline(OnlineClient.uri("127.0.0.1:" + server.port()), "Ann", "flat", 2, List.of(), null, code -> {
                Thread bob = new Thread(() -> {
                    try {
                        new HeadlessPlayer(new HeadlessPlayer.Options(OnlineClient.uri("127.0.0.1:" + server.port()), null, 0,
                                List.of(), true, code, "Bob", "straight", null, 0), bobsCard::set, line -> { }, null).run();
                    } catch (Throwable t) {
                        bobFailed.set(t);
                    }
                });
                bob.setDaemon(true);
                bob.start();
            });
            app.run();

            assertTrue(sawLobby[0] && sawPlay[0], "the lobby, then play");
            RoundGame round = app.roundGame();
            assertNotNull(round);
            assertTrue(round.isOver(), "the hole was played to the end");
            assertTrue(finalCardPasses[0] >= 5, "the final card was shown");
            assertEquals(app.screens().online(), app.screen(), "after an online round Play again opens Play online");
            assertEquals(1, round.finishedScores()[0][0], "Ann's scripted putt holes: v = sqrt(2 mu g d) at the hole");
            assertTrue(sawReplay[0], "the hole was watched again");
            assertArrayEquals(new int[]{1 + round.finishedScores()[0][1], 0}, app.replayCounts(),
                    "every stroke of the online hole replayed, none ended elsewhere than the server ended it");
            for (int i = 0; i < 100 && bobsCard.get() == null && bobFailed.get() == null; i++) Thread.sleep(100);
            assertNull(bobFailed.get());
            JsonNode card = Json.parse(bobsCard.get());
            assertEquals(round.finishedScores()[0][1], card.get("players").get(1).get("total").asInt(), "both sides agree on Bob");
            assertEquals(1, card.get("players").get(0).get("total").asInt());

            // The seat is remembered; the round saves and loads back as hot seat's do.
            OnlineMemory memory = OnlineMemory.load(OnlineMemory.file(config));
            assertEquals(card.get("room").asText(), memory.room());
            assertEquals("127.0.0.1:" + server.port(), memory.server(), "the server the seat is on, to resume it there");
            assertEquals("Ann", memory.name());
            assertTrue(minigolf.online.Protocol.TOKEN.matcher(memory.token()).matches(), "the seat's token, to resume it");
            Path save = dir.resolve("online-round.json");
            SavedRounds.save(round, save);
            assertEquals(round.scorecard().toText(), SavedRounds.load(save).scorecard().toText());
            assertTrue(Files.size(save) > 0);
        }
    }
}
