package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_V;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Lab furniture out of a player's view: the vx/vy/vz Shot panel was always on screen. It belongs to
 * practice mode, off by default; V (or Settings) brings it back, and it is kept in the settings file.
 */
class PracticeModeTest {
    @TempDir
    Path dir;

    private GameApp app(List<Player> players) {
        GameApp app = new GameApp(GameLauncher.loadBundled("/courses/flat.json"), new GameApp.Options(null, null, 0, null,
                List.of(), 1, new SettingsStore(dir), false, false));
        app.startGame(players);
        return app;
    }

    @Test
    void theShotPanelIsOffByDefaultAndVBringsItBack() throws Exception {
        assertFalse(UserSettings.DEFAULTS.practice(), "off by default");
        GameApp app = app(List.of(Player.human("Ann")));
        PlayingScreen playing = app.screens().playing();
        app.setScreen(playing);
        assertFalse(playing.showsShotPanel(), "a player's view has no Shot panel");
        assertTrue(playing.keyPressed(GLFW_KEY_V, 0));
        assertTrue(playing.showsShotPanel(), "V: practice mode, the Shot panel");
        assertTrue(new SettingsStore(dir).load().practice(), "kept for next time");
        playing.keyPressed(GLFW_KEY_V, 0);
        assertFalse(playing.showsShotPanel(), "V again: gone");
        assertFalse(new SettingsStore(dir).load().practice());
    }

    @Test
    void aBotsTurnHasNoShotPanelEvenInPracticeMode() {
        GameApp app = app(List.of(Player.bot("Bot (Medium)", "medium")));
        app.applySettings(app.settings().withPractice(true));
        app.setScreen(app.screens().playing());
        assertFalse(app.screens().playing().showsShotPanel());
    }
}
