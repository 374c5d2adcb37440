package minigolf.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import minigolf.ui.Screen;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Every menu screen and the HUD with the shot panel drawn in the real game window under Xvfb (the
 * pictures go to build/screenshots/screen-*.png to be looked at): each opens as its button would,
 * stays open, and draws.
 */
@minigolf.render.NeedsDisplay
class ScreensWindowTest {
    @TempDir
    Path dir;

    private Path shot(Screen screen, List<Player> players) throws Exception {
        Path projectDir = Path.of(System.getProperty("minigolf.projectDir", "."));
        Path shots = projectDir.resolve("build").resolve("screenshots");
        Files.createDirectories(shots);
        Path png = shots.resolve("screen-" + screen.name().toLowerCase(java.util.Locale.ROOT) + ".png");
        Files.deleteIfExists(png);
        World world = World.load(projectDir.resolve("courses").resolve("lake.json"));
        GameApp app = new GameApp(world, new GameApp.Options(null, png, 8, players, List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
        app.onLoopPass((pass, window) -> {
            if (pass == 1) app.showScreen(screen);
        });
        app.run();
        assertEquals(screen, app.screen());
        assertTrue(Files.size(png) > 10_000, png + " was written");
        return png;
    }

    @Test
    void theMenusOpenAndDraw() throws Exception {
        // A saved game first, so that the main menu shows "Load saved game".
        Path projectDir = Path.of(System.getProperty("minigolf.projectDir", "."));
        GameApp saver = new GameApp(World.load(projectDir.resolve("courses").resolve("lake.json")), new GameApp.Options(null,
                null, 3, List.of(Player.human("Ann")), List.of(), 1, new SettingsStore(dir.resolve("config")), true, false));
        saver.onLoopPass((pass, window) -> {
            if (pass == 1) saver.saveGame();
        });
        saver.run();
        assertEquals(1, saver.savedGames().size(), "a game was saved");
        for (Screen s : new Screen[]{Screen.MAIN_MENU, Screen.COURSES, Screen.NEW_GAME, Screen.SETTINGS, Screen.HELP}) {
            shot(s, null);
        }
    }

    @Test
    void theHudWithTheShotPanelAndThePauseMenu() throws Exception {
        shot(Screen.PLAYING, List.of(Player.human("Ann"), Player.human("Bob")));
        shot(Screen.PAUSED, List.of(Player.human("Ann")));
    }
}
