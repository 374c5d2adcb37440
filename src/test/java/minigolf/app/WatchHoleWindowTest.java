package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.SettingsStore;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Any hole of a saved round watched again in the real window, after loading it: every stroke ends as in play. */
@minigolf.render.NeedsDisplay
class WatchHoleWindowTest {
    @TempDir
    Path dir;

    private static World flat(double hx) throws Exception {
        return World.parse("{\"format\": 1, \"name\": \"Flat " + hx + "\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-3, 0], \"hole\": {\"position\": [" + hx + ", 0], \"radius\": 0.1}}", "flat");
    }

    @Test
    void theFirstHoleOfALoadedRoundIsReplayedExactly() throws Exception {
        double mg = 0.1 * 9.81;
        Round round = new Round("Two", List.of(new Round.Hole("a.json", 2, flat(1)), new Round.Hole("b.json", 2, flat(2))), "test");
        RoundGame rg = new RoundGame(round, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
        // Hole 1 (cup 4 m away): 2.5 m short, then the last 1.5 m.
        assertEquals(Outcome.STOPPED, rg.game().play(Math.sqrt(2 * mg * 2.5), 0.01).outcome());
        double x = rg.game().player(0).x(), y = rg.game().player(0).y(), dx = 1 - x, dy = -y, d = Math.hypot(dx, dy);
        assertEquals(Outcome.HOLED, rg.game().play(Math.sqrt(2 * mg * d) * dx / d, Math.sqrt(2 * mg * d) * dy / d).outcome());
        rg.finishHole();
        assertTrue(rg.nextHole());
        Path file = dir.resolve("round.json");
        SavedRounds.save(rg, file);

        GameApp.Options options = new GameApp.Options(null, null, 3000, List.of(Player.human("Ann")), List.of(), 10,
                new SettingsStore(dir.resolve("config")), true, false);
        GameApp app = new GameApp(GameLauncher.loadBundled("/courses/flat.json"), options);
        int[] step = {0};
        boolean[] sawReplay = {false};
        String[] replayedCourse = {null};
        app.onLoopPass((pass, window) -> {
            if (step[0] == 0 && pass > 2) {
                app.loadGame(file);
                step[0] = 1;
            } else if (step[0] == 1 && app.screen() == app.screens().playing() && app.roundGame() != null) {
                app.watchHole(0);
                step[0] = 2;
            } else if (step[0] == 2 && app.screen() == app.screens().replay()) {
                sawReplay[0] = true;
                replayedCourse[0] = app.shownWorld().course().name();
            } else if (step[0] == 2 && sawReplay[0] && app.screen() == app.screens().playing()) {
                window.requestClose();
            }
        });
        app.run();
        assertTrue(sawReplay[0], "the replay was shown");
        assertEquals("Flat 1.0", replayedCourse[0], "hole 1's course on screen while it is watched");
        assertEquals("Flat 2.0", app.world().course().name(), "back to the hole being played");
        assertArrayEquals(new int[]{2, 0}, app.replayCounts(), "both strokes of hole 1 replayed, none ended elsewhere");
    }
}
