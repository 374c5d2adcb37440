package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.glfw.GLFW.glfwIconifyWindow;
import static org.lwjgl.glfw.GLFW.glfwRestoreWindow;
import static org.lwjgl.glfw.GLFW.glfwSetWindowSize;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real game window under Xvfb while a ball rolls: it is resized, minimised and restored, then
 * closed mid-shot. The game must go on drawing at the new size and shut down cleanly.
 */
@minigolf.render.NeedsDisplay
class GameWindowEventsTest {
    @TempDir
    Path dir;

    @Test
    void resizeMinimiseAndCloseMidShot() {
        World flat = GameLauncher.loadBundled("/courses/flat.json");
        // A slow-motion shot (a quarter of real time) so the ball is still rolling when the window closes.
        GameApp.Options options = new GameApp.Options(null, null, 0, List.of(Player.human("Ann")),
                List.of(new double[]{3.5, 0}), 0.25, new SettingsStore(dir.resolve("config")), true, false);
        GameApp app = new GameApp(flat, options);
        List<Integer> widthsAfterResize = new ArrayList<>();
        boolean[] closedMidShot = {false};
        app.onLoopPass((pass, window) -> {
            long h = window.handle();
            if (pass == 3) glfwSetWindowSize(h, 640, 400);
            if (pass >= 6 && pass < 9) widthsAfterResize.add(window.framebufferWidth());
            if (pass == 9) glfwIconifyWindow(h);
            if (pass == 12) glfwRestoreWindow(h);
            if (pass == 15) glfwSetWindowSize(h, 1024, 600);
            if (pass >= 18) {
                closedMidShot[0] = app.game().isShotInFlight();
                window.requestClose();
            }
        });
        Game game = app.run();

        assertTrue(closedMidShot[0], "the window closed while the ball was rolling");
        assertTrue(widthsAfterResize.contains(640), "framebuffer widths after the resize: " + widthsAfterResize);
        // The shot is still the one in flight; nothing was scored or lost on the way out.
        assertEquals(1, game.players().size());
        assertTrue(game.isShotInFlight());
        assertFalse(game.isOver());
    }
}
