package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import minigolf.render.BallView;
import minigolf.render.ObjectsPass;
import minigolf.ui.PlayerColors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Which ball is mine, in the real window: at the start of a three-player hot-seat hole each ball
 * stands on its own spot in its player's colour (before, all three were drawn on the tee and the
 * last one drawn, Cy's, was what showed for "Ann to play"), the ball to play is ringed, a name
 * tag stands over each ball (Ann's in gold), and a rolling ball draws a trail that is gone when it
 * stops.
 */
@minigolf.render.NeedsDisplay
class BallIdentityWindowTest {
    @TempDir
    Path dir;

    private static int[] rgb(BufferedImage image, float[] p) {
        int c = image.getRGB(Math.round(p[0]), Math.round(p[1]));
        return new int[]{(c >> 16) & 255, (c >> 8) & 255, c & 255};
    }

    @Test
    void threeBallsOnTheirOwnSpotsInTheirColoursRingedNamedAndTrailed() throws Exception {
        Path projectDir = Path.of(System.getProperty("minigolf.projectDir", "."));
        Path file = projectDir.resolve("courses/holes/01-first-tee.json");
        Path png = projectDir.resolve("build/screenshots/three-balls.png");
        Files.createDirectories(png.getParent());
        List<Player> players = List.of(Player.human("Ann"), Player.human("Bob"), Player.human("Cy"));
        GameApp app = new GameApp(World.load(file), new GameApp.Options(file, png, 60, players, List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
        List<float[]> centres = new ArrayList<>();
        BallView[] ringed = new BallView[1];
        List<GameScreen.NameTag> tags = new ArrayList<>();
        app.onLoopPass((pass, window) -> {
            if (pass != 59) return;
            // The camera has settled on Ann's ball: where each ball's centre shows in the picture.
            for (int i = 0; i < 3; i++) {
                var s = app.game().player(i);
                double z = app.world().terrain().height(s.x(), s.y()) + ObjectsPass.visualBallRadius();
                float[] p = app.scene().camera().project(new org.joml.Vector3f((float) s.x(), (float) s.y(), (float) z),
                        window.framebufferWidth(), window.framebufferHeight());
                centres.add(p);
            }
            ringed[0] = app.scene().renderer().objectsPass().marker();
            tags.addAll(app.screens().playing().lastNameTags());
        });
        app.run();

        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(3, centres.size());
        for (int i = 0; i < 3; i++) {
            float[] want = PlayerColors.of(i);
            int[] got = rgb(image, centres.get(i));
            // Lit from the sun the ball is darker on one side: compare hues, each channel within a generous band.
            for (int k = 0; k < 3; k++) {
                assertEquals(want[k] * 255 * 0.85, got[k], 70, players.get(i).name() + "'s ball shows its colour, got "
                        + got[0] + "," + got[1] + "," + got[2]);
            }
            for (int j = 0; j < i; j++) {
                double apart = Math.hypot(centres.get(i)[0] - centres.get(j)[0], centres.get(i)[1] - centres.get(j)[1]);
                assertTrue(apart > 10, "balls " + j + " and " + i + " are " + apart + " pixels apart");
            }
        }
        assertNotNull(ringed[0], "the ball to play is ringed");
        assertEquals(app.game().player(0).x(), ringed[0].x(), 1e-6, "Ann's ball is ringed");
        assertEquals(app.game().player(0).y(), ringed[0].y(), 1e-6);
        assertEquals(List.of("Ann", "Bob", "Cy"), tags.stream().map(GameScreen.NameTag::name).toList());
        assertEquals(List.of(true, false, false), tags.stream().map(GameScreen.NameTag::current).toList(), "Ann's tag is gold");
        for (int i = 0; i < 3; i++) {
            GameScreen.NameTag t = tags.get(i);
            assertTrue(t.y() < centres.get(i)[1], "the tag stands over the ball");
            assertEquals(centres.get(i)[0], t.x(), 1.5, "straight over it");
            for (int j = 0; j < i; j++) {
                GameScreen.NameTag u = tags.get(j);
                assertFalse(NameTagLayout.overlap(t.x(), t.y(), t.width(), t.height(), u.x(), u.y(), u.width(), u.height()),
                        t + " covers " + u);
            }
        }
    }

    @Test
    void aRollingBallDrawsATrailThatGoesWhenItStops() throws Exception {
        World flat = GameLauncher.loadBundled("/courses/flat.json");
        GameApp app = new GameApp(flat, new GameApp.Options(null, null, 400, List.of(Player.human("Ann")),
                List.of(new double[]{2.5, 0}), 1, new SettingsStore(dir.resolve("config")), true, false));
        boolean[] trailWhileRolling = {false}, trailAtRest = {false};
        int[] restFrames = {0};
        app.onLoopPass((pass, window) -> {
            if (app.scene().renderer() == null || app.game() == null) return;
            boolean trail = app.scene().renderer().objectsPass().hasTrail();
            if (app.game().isShotInFlight()) trailWhileRolling[0] |= trail;
            else if (!app.game().history().isEmpty() && ++restFrames[0] > 2) trailAtRest[0] |= trail;
            if (restFrames[0] > 10) window.requestClose();
        });
        app.run();
        assertEquals(1, app.game().history().size(), "the stroke was played");
        assertTrue(trailWhileRolling[0], "a trail behind the rolling ball");
        assertTrue(!trailAtRest[0], "no trail once it stopped");
    }
}
