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
        boolean[] sawCardBetween = {false}, clearanceInPlay = {false};
        // The camera as the final card's frames left it (the hook runs before each frame): target, yaw, shift, clearance.
        List<float[]> cardViews = new java.util.ArrayList<>();
        boolean[] cardClearance = {false};
        app.onLoopPass((pass, window) -> {
            RoundGame rg = app.roundGame();
            if (rg != null && app.screen() == app.screens().roundCard() && !rg.isOver()) sawCardBetween[0] = true;
            if (app.screen() == app.screens().playing() && app.scene().camera() != null && app.scene().camera().clearance() != null) clearanceInPlay[0] = true;
            if (rg != null && rg.isOver() && app.screen() == app.screens().roundCard() && app.scene().camera() != null) {
                org.joml.Vector3f t = app.scene().camera().target();
                cardViews.add(new float[]{t.x, t.y, app.scene().camera().yaw(), app.scene().camera().screenShiftX(), app.scene().camera().pitch()});
                cardClearance[0] |= app.scene().camera().clearance() != null;
            }
        });
        app.run();

        RoundGame rg = app.roundGame();
        assertTrue(rg.isOver());
        assertTrue(sawCardBetween[0], "the card was shown between the holes");
        assertEquals(app.screens().roundCard(), app.screen());
        assertArrayEquals(new int[]{1}, rg.finishedScores()[0]);
        assertArrayEquals(new int[]{1}, rg.finishedScores()[1]);
        assertEquals(4, rg.scorecard().totalPar());
        assertEquals(-2, rg.scorecard().toPar(0), "two aces on two par-2 holes");
        HighScores h = HighScores.load(HighScores.file(dir.resolve("config")));
        assertEquals(2, h.table("Two of Meadowbrook").get(0).score());
        assertEquals(1, h.personalBest("Two of Meadowbrook", 1, "Ann"));
        assertTrue(Files.size(shots.resolve("round-card.png")) > 10_000);

        // Behind the final card the camera shows the whole last course (Tree Slalom), turning, right of the card.
        assertTrue(clearanceInPlay[0], "while playing, the camera keeps the ball clear of the trees");
        assertTrue(cardViews.size() >= 2, "final card frames seen: " + cardViews.size());
        float[] last = cardViews.get(cardViews.size() - 1), before = cardViews.get(0);
        minigolf.course.Bounds b = full.hole(5).world().course().bounds();
        assertEquals(0.5 * (b.minX() + b.maxX()), last[0], 1e-4, "looking at the course's middle");
        assertEquals(0.5 * (b.minY() + b.maxY()), last[1], 1e-4);
        assertEquals(CourseScene.CARD_SHIFT_X, last[3], 0, "the course shows right of the card");
        assertEquals(CourseScene.CARD_PITCH, last[4], 1e-5);
        assertTrue(last[2] != before[2], "the view turns: yaw " + before[2] + " -> " + last[2]);
        assertFalse(cardClearance[0], "no clearance pulls the overview into the crowns round the middle");

        // The help screen, as F1 opens it, over the course.
        GameApp help = new GameApp(full.hole(2).world(), new GameApp.Options(null, shots.resolve("help.png"), 6, null, List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
        help.onLoopPass((pass, window) -> {
            if (pass == 0) help.openHelp();
        });
        help.run();
        assertEquals(help.screens().help(), help.screen());
        assertTrue(Files.size(shots.resolve("help.png")) > 10_000);
    }
}
