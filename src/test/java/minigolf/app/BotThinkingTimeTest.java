package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A computer opponent's turn shows "... is thinking" for a moment a player can see: the levels
 * decide within a frame or two, and their stroke came in the next frame (no "thinking" on screen).
 */
class BotThinkingTimeTest {
    @TempDir
    Path dir;

    @Test
    void aBotThatDecidesAtOnceStillThinksForTheLeastTimeAndItsBarNeverRunsAhead() throws Exception {
        World tee = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/holes/01-first-tee.json"));
        PlaySession play = new PlaySession(tee, null, List.of(), new PlayerFiles(new SettingsStore(dir), s -> { }), s -> { });
        play.start(List.of(Player.bot("Bot (Hard)", "hard")), UserSettings.DEFAULTS);
        double step = 0.02, played = 0;
        long deadline = System.nanoTime() + 60_000_000_000L;
        play.advance(step, 1, false); // the turn starts
        assertNotNull(play.botTurn());
        // No play time passes until the bot has decided: it is done at 0 s of its turn.
        while (!play.botTurn().isDone() && System.nanoTime() < deadline) Thread.sleep(5);
        assertTrue(play.botTurn().isDone(), "Hard decided within a minute");
        assertEquals(0, play.botProgress(), 1e-12, "the bar starts empty though the bot is done");
        while (play.animator() == null && played < 5) {
            play.advance(step, 1, false);
            played += step;
            if (play.animator() == null) {
                assertTrue(play.botProgress() <= played / PlaySession.MIN_THINKING_SECONDS + 1e-9, "bar at " + play.botProgress());
            }
        }
        assertNotNull(play.animator(), "the stroke was played");
        assertEquals(PlaySession.MIN_THINKING_SECONDS, played, step + 1e-9, "the stroke came after the least thinking time");
    }
}
