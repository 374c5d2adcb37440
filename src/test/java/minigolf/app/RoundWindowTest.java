package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.HighScores;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.RoundLoader;
import minigolf.game.RoundFilesTest;
import minigolf.game.SettingsStore;
import minigolf.render.Png;
import minigolf.ui.Screen;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A round in the real game window under Xvfb: two holes of Meadowbrook played with scripted aces
 * through the game's HIT input, the card between the holes, the final card, the high-score file,
 * and the help screen.
 */
@minigolf.render.NeedsDisplay
class RoundWindowTest {
    @TempDir
    Path dir;

    @Test
    void twoHolesWithAcesThenTheFinalCardAndTheHighScores() throws Exception {
        Path rounds = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "rounds");
        Round full = RoundLoader.load(rounds.resolve("meadowbrook-18.json"));
        Round two = new Round("Two of Meadowbrook", List.of(full.hole(0), full.hole(5)), "test");
        Path shots = Path.of(System.getProperty("minigolf.projectDir", "."), "build", "screenshots");
        Files.createDirectories(shots);
        GameApp.Options options = new GameApp.Options(null, shots.resolve("round-card.png"), 4000, List.of(Player.human("Ann")),
                List.of(RoundFilesTest.HOLE_IN_ONE[0], RoundFilesTest.HOLE_IN_ONE[5]), 20,
                new SettingsStore(dir.resolve("config")), true, true);
        GameApp app = new GameApp(full.hole(0).world(), options);
        app.playRound(two);
        boolean[] sawCardBetween = {false};
        app.onLoopPass((pass, window) -> {
            RoundGame rg = app.roundGame();
            if (rg != null && app.screen() == Screen.ROUND_CARD && !rg.isOver()) sawCardBetween[0] = true;
        });
        app.run();

        RoundGame rg = app.roundGame();
        assertTrue(rg.isOver());
        assertTrue(sawCardBetween[0], "the card was shown between the holes");
        assertEquals(Screen.ROUND_CARD, app.screen());
        assertArrayEquals(new int[]{1}, rg.finishedScores()[0]);
        assertArrayEquals(new int[]{1}, rg.finishedScores()[1]);
        assertEquals(4, rg.scorecard().totalPar());
        assertEquals(-2, rg.scorecard().toPar(0), "two aces on two par-2 holes");
        HighScores h = HighScores.load(HighScores.file(dir.resolve("config")));
        assertEquals(2, h.table("Two of Meadowbrook").get(0).score());
        assertEquals(1, h.personalBest("Two of Meadowbrook", 1, "Ann"));
        assertTrue(Files.size(shots.resolve("round-card.png")) > 10_000);

        // The help screen, as F1 opens it, over the course.
        GameApp help = new GameApp(full.hole(2).world(), new GameApp.Options(null, shots.resolve("help.png"), 6, null, List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
        help.onLoopPass((pass, window) -> {
            if (pass == 0) help.openHelp();
        });
        help.run();
        assertEquals(Screen.HELP, help.screen());
        assertTrue(Files.size(shots.resolve("help.png")) > 10_000);
    }
}
