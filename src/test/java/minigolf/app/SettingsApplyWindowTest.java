package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.render.RenderQuality;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.lwjgl.glfw.GLFW.glfwGetWindowSize;

/** The Display settings in the real window: a new size and graphics quality apply at once and are saved. */
@minigolf.render.NeedsDisplay
class SettingsApplyWindowTest {
    @TempDir
    Path dir;

    @Test
    void windowSizeAndGraphicsQualityApplyAtOnce() throws Exception {
        SettingsStore store = new SettingsStore(dir.resolve("config"));
        GameApp app = new GameApp(GameLauncher.loadBundled("/courses/flat.json"), new GameApp.Options(null, null, 40,
                List.of(Player.human("Ann")), List.of(), 1, store, true, false));
        int[] size = new int[2];
        RenderQuality[] quality = new RenderQuality[1];
        app.onLoopPass((pass, window) -> {
            if (pass == 5) {
                app.applySettings(app.settings().withWindowSize(1024, 640).withGraphics("low"));
            } else if (pass == 20) {
                int[] w = new int[1], h = new int[1];
                glfwGetWindowSize(window.handle(), w, h);
                size[0] = w[0];
                size[1] = h[0];
                quality[0] = app.renderQuality();
            }
        });
        app.run();
        assertArrayEquals(new int[]{1024, 640}, size, "the window took the new size");
        assertSame(RenderQuality.SOFTWARE, quality[0], "low graphics: the software quality");
        assertEquals("low", store.load().graphics());
        assertEquals(1024, store.load().windowWidth());
    }
}
