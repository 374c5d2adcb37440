package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A settings notice (a settings file that could not be read) and a computer opponent thinking, both
 * at the top of the screen: the bot's panel hangs below the notice instead of over it (before, both
 * were centred at the top, 12 and 16 units down, and the panel covered the notice's text and its
 * Dismiss button).
 */
@minigolf.render.NeedsDisplay
class NoticeAndBotPanelWindowTest {
    @TempDir
    Path dir;

    @Test
    void theBotsPanelIsDrawnBelowTheNotice() throws Exception {
        SettingsStore store = BrokenSettings.in(dir);
        Path course = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "holes", "01-first-tee.json");
        GameApp app = new GameApp(World.load(course), new GameApp.Options(course, null, 2000,
                List.of(Player.human("Ann"), Player.bot("Bot (Hard)", "hard")), List.of(new double[]{3.0, 0.05}), 1,
                store, true, false));
        assertNotNull(app.notice(), "the broken settings file gives a notice");
        float[][] seen = new float[2][];
        int[] frames = {0};
        app.finishWhen(() -> {
            float[] notice = app.toasts().noticeRect(), bot = app.hud().botPanel();
            // Frames where both are on screen (a new window measures itself off screen first).
            if (notice != null && bot != null && notice[1] >= 0 && bot[1] >= 0) {
                seen[0] = notice;
                seen[1] = bot;
                return ++frames[0] >= 3;
            }
            return false;
        });
        app.run();
        assertTrue(frames[0] >= 1, "a frame showed the notice and the bot's panel together");
        float[] notice = seen[0], bot = seen[1];
        assertTrue(bot[1] >= notice[1] + notice[3], "the bot's panel " + Arrays.toString(bot) + " starts below the notice "
                + Arrays.toString(notice));
    }
}
