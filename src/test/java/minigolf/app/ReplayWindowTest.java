package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** "Watch again" in the real window: the finished hole's strokes are animated again and each ends where it did in play. */
@minigolf.render.NeedsDisplay
class ReplayWindowTest {
    @TempDir
    Path dir;

    @Test
    void watchAgainReplaysEveryStrokeExactly() {
        World flat = GameLauncher.loadBundled("/courses/flat.json");
        // Two putts on the flat course (start (-3, 0), hole (3, 0.5)): 4 m along x, then the last 2.06 m to the cup
        // (a putt rolls v^2 / (2 mu g), mu 0.1).
        double mg = 0.1 * 9.81, d = Math.hypot(2, 0.5);
        GameApp.Options options = new GameApp.Options(null, null, 3000, List.of(Player.human("Ann")),
                List.of(new double[]{Math.sqrt(2 * mg * 4), 0}, new double[]{Math.sqrt(2 * mg * d) * 2 / d, Math.sqrt(2 * mg * d) * 0.5 / d}), 10,
                new SettingsStore(dir.resolve("config")), true, false);
        GameApp app = new GameApp(flat, options);
        boolean[] asked = {false}, sawReplay = {false};
        app.onLoopPass((pass, window) -> {
            if (app.screen() == app.screens().replay()) sawReplay[0] = true;
            if (!asked[0] && app.screen() == app.screens().scorecard()) {
                asked[0] = true;
                app.watchReplay();
            } else if (asked[0] && app.screen() == app.screens().scorecard()) {
                window.requestClose();
            }
        });
        app.run();
        assertTrue(app.game().isOver(), "the hole was played out: " + app.game().states());
        assertTrue(sawReplay[0], "the replay was shown");
        assertEquals(2, app.game().history().size());
        assertArrayEquals(new int[]{2, 0}, app.replayCounts(), "both strokes replayed, none ended elsewhere");
    }
}
