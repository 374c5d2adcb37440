package minigolf.app;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.function.Function;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import minigolf.ui.Screen;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_F1;

/**
 * Every menu screen and the HUD with the shot panel drawn in the real game window under Xvfb (the
 * pictures go to build/screenshots/screen-*.png to be looked at): each opens as its button would,
 * stays open, and draws. And the ways between the screens: ESC, F1, Settings and Help going back
 * to where they were opened, the main menu's buttons.
 */
@minigolf.render.NeedsDisplay
class ScreensWindowTest {
    @TempDir
    Path dir;

    private GameApp app(int frames, Path png, List<Player> players) throws Exception {
        World world = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "lake.json"));
        return new GameApp(world, new GameApp.Options(null, png, frames, players, List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
    }

    private void shot(String name, Consumer<GameApp> open, Function<GameApp, Screen> expected, List<Player> players)
            throws Exception {
        Path shots = Path.of(System.getProperty("minigolf.projectDir", "."), "build", "screenshots");
        Files.createDirectories(shots);
        Path png = shots.resolve("screen-" + name + ".png");
        Files.deleteIfExists(png);
        GameApp app = app(8, png, players);
        app.onLoopPass((pass, window) -> {
            if (pass == 1) open.accept(app);
        });
        app.run();
        assertSame(expected.apply(app), app.screen(), name);
        assertTrue(Files.size(png) > 10_000, png + " was written");
    }

    @Test
    void theMenusOpenAndDraw() throws Exception {
        // A saved game first, so that the main menu shows "Load saved game".
        GameApp saver = app(3, null, List.of(Player.human("Ann")));
        saver.onLoopPass((pass, window) -> {
            if (pass == 1) saver.saveGame();
        });
        saver.run();
        assertEquals(1, saver.savedGames().size(), "a game was saved");
        shot("main_menu", a -> { }, a -> a.screens().mainMenu(), null);
        shot("courses", a -> a.setScreen(a.screens().courseSelect()), a -> a.screens().courseSelect(), null);
        shot("new_game", a -> a.setScreen(a.screens().newGame()), a -> a.screens().newGame(), null);
        shot("settings", GameApp::openSettings, a -> a.screens().settings(), null);
        shot("help", GameApp::openHelp, a -> a.screens().help(), null);
    }

    @Test
    void theHudWithTheShotPanelAndThePauseMenu() throws Exception {
        shot("playing", a -> { }, a -> a.screens().playing(), List.of(Player.human("Ann"), Player.human("Bob")));
        shot("paused", a -> a.setScreen(a.screens().pause()), a -> a.screens().pause(), List.of(Player.human("Ann")));
    }

    @Test
    void choosingAComputerOpponentLeavesTheFormWhereItWas() throws Exception {
        // The form grew by the level buttons and re-centred: "Tee off" moved from under the mouse.
        GameApp app = app(24, null, null);
        NewGameScreen form = app.screens().newGame();
        float[][] rects = new float[2][];
        app.onLoopPass((pass, window) -> {
            if (pass == 1) app.setScreen(form);
            if (pass == 10) {
                rects[0] = form.lastRect();
                form.chooseOpponent(1, "hard");
            }
            if (pass == 20) rects[1] = form.lastRect();
        });
        app.run();
        assertEquals("Bot (Hard)", form.name(1));
        for (int k = 0; k < 3; k++) assertEquals(rects[0][k], rects[1][k], 0.5f, "x, y, width: " + k);
    }

    /** Presses a key as the window would: the screen shown first, then the keys that work everywhere. */
    private static void press(GameApp app, int key) {
        if (!app.screen().keyPressed(key, 0) && key == GLFW_KEY_F1) app.openHelp();
    }

    @Test
    void escHelpAndSettingsGoBackToWhereTheyWereOpened() throws Exception {
        GameApp app = app(0, null, List.of(Player.human("Ann")));
        List<Screen> seen = new ArrayList<>();
        Runnable[] steps = {
                () -> press(app, GLFW_KEY_ESCAPE),   // playing -> pause
                app::openSettings,                   // pause -> settings (the pause menu's button)
                () -> press(app, GLFW_KEY_ESCAPE),   // settings -> back to pause
                () -> press(app, GLFW_KEY_F1),       // pause -> help
                () -> press(app, GLFW_KEY_F1),       // F1 again: back to pause
                () -> press(app, GLFW_KEY_ESCAPE),   // pause -> playing
                () -> press(app, GLFW_KEY_F1),       // playing -> help
                () -> press(app, GLFW_KEY_ESCAPE),   // help -> playing
                app::toMainMenu,                     // the pause menu's "Main menu"
                () -> app.setScreen(app.screens().newGame()),
                () -> press(app, GLFW_KEY_ESCAPE),   // new game -> main menu
                app::openSettings,
                () -> app.screens().settings().apply(), // Apply -> back to the main menu
        };
        app.onLoopPass((pass, window) -> {
            if (pass >= 2 && pass % 2 == 0 && (pass - 2) / 2 < steps.length) {
                steps[(pass - 2) / 2].run();
                seen.add(app.screen());
            }
            if (pass > 2 * steps.length + 4) window.requestClose();
        });
        app.run();
        GameApp.Screens s = app.screens();
        assertEquals(List.of(s.pause(), s.settings(), s.pause(), s.help(), s.pause(), s.playing(), s.help(), s.playing(),
                s.mainMenu(), s.newGame(), s.mainMenu(), s.settings(), s.mainMenu()), seen);
        assertNull(app.game(), "the main menu ended the game");
    }
}
