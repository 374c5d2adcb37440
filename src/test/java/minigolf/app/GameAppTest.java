package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerStatus;
import minigolf.game.SavedGames;
import minigolf.game.ScoreLine;
import minigolf.game.SettingsStore;
import minigolf.physics.Outcome;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real game window under Xvfb: a scripted two-player game on the flat course goes through the
 * same input path as the HIT button ({@link GameApp#hit}), animated at the fixed physics step.
 */
@minigolf.render.NeedsDisplay
class GameAppTest {
    @TempDir
    Path dir;

    private static final double MU_G = 0.1 * 9.81;

    private static double[] shot(double fx, double fy, double tx, double ty, double fraction) {
        double dx = tx - fx, dy = ty - fy, d = Math.hypot(dx, dy), v = Math.sqrt(2 * MU_G * d * fraction);
        return new double[]{dx / d * v, dy / d * v};
    }

    @Test
    void scriptedTwoPlayerGameInTheWindow() throws Exception {
        World flat = GameLauncher.loadBundled("/courses/flat.json");
        // Each ball on its own spot beside the tee (-3, 0).
        List<minigolf.course.Vec2> tee = minigolf.game.TeeSpots.of(flat, 2);
        double ax = tee.get(0).x(), ay = tee.get(0).y(), bx = tee.get(1).x(), by = tee.get(1).y();
        List<double[]> shots = List.of(
                shot(ax, ay, 3, 0.5, 0.5),  // Ann: half-way
                new double[]{-3.9, 0.1},    // Bob: out of bounds, penalty, back to his spot
                shot(bx, by, 3, 0.5, 1),    // Bob: holed
                shot((ax + 3) / 2, (ay + 0.5) / 2, 3, 0.5, 1)); // Ann: holed
        Path shots_ = Path.of(System.getProperty("minigolf.projectDir", "."), "build", "screenshots");
        Files.createDirectories(shots_);
        Path png = shots_.resolve("game-scorecard.png");
        GameApp.Options options = new GameApp.Options(null, png, 3000, List.of(Player.human("Ann"), Player.human("Bob")),
                shots, 40, new SettingsStore(dir.resolve("config")), true, true);
        GameApp app = new GameApp(flat, options);
        Game game = app.run();

        assertEquals(app.screens().scorecard(), app.screen());
        assertTrue(game.isOver());
        List<Outcome> outcomes = game.history().stream().map(r -> r.outcome()).toList();
        assertEquals(List.of(Outcome.STOPPED, Outcome.OUT, Outcome.HOLED, Outcome.HOLED), outcomes);
        assertEquals(new ScoreLine("Ann", 2, 0, PlayerStatus.HOLED, 2, 1), game.scorecard().lines().get(0));
        assertEquals(new ScoreLine("Bob", 2, 1, PlayerStatus.HOLED, 3, 2), game.scorecard().lines().get(1));

        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(1280, image.getWidth());
        // The scorecard panel (dark green, alpha 0.9) stands at the left, the course turning beside it:
        // a column just inside its right edge, below the title, is mostly the panel's colour.
        int dark = 0, samples = 0;
        for (int y = 330; y <= 420; y += 6, samples++) {
            int rgb = image.getRGB(422, y);
            int r = (rgb >> 16) & 255, g = (rgb >> 8) & 255, b = rgb & 255;
            if (g < 90 && r < 60 && b < 60) dark++;
        }
        assertTrue(dark > samples * 0.8, "the panel's dark green at the left: " + dark + " of " + samples);
        int rgb = image.getRGB(1000, 450); // the course right of it
        int r = (rgb >> 16) & 255, g = (rgb >> 8) & 255, b = rgb & 255;
        assertTrue(g > 110 && g > r + 30, "the course's grass beside the card, got " + r + "," + g + "," + b);

        // The finished game saves and loads back to the same state.
        Path save = dir.resolve("save.json");
        SavedGames.save(game, save);
        assertEquals(game.state(), SavedGames.load(save).resume().state());
        assertTrue(Files.size(save) > 100);
    }
}
