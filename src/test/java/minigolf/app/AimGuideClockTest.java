package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.AimGuide;
import minigolf.game.Game;
import minigolf.game.PlayerState;
import minigolf.game.SettingsStore;
import minigolf.game.ShotRecord;
import minigolf.physics.World;
import minigolf.render.AimView;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The aim guide on a course whose obstacles move shows the stroke the player will get: the one hit
 * at the clock a release starts it at, not at clock 0. On the practice windmill (blades turning once
 * every 4 s before the door) a 3.5 m/s putt along the lane is stopped by a blade when hit at clock 0
 * (it comes back to x = -1.09) and passes when hit half a second later (it stops at x = 2.84).
 */
class AimGuideClockTest {
    @TempDir
    Path dir;

    @Test
    void theGuideIsTheStrokeHitAtTheGamesClock() throws Exception {
        World windmill = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "practice", "windmill.json"));
        GameApp app = new GameApp(windmill, new GameApp.Options(null, null, 0, null, List.of(), 1, new SettingsStore(dir),
                false, false));
        NewGameScreen form = app.screens().newGame();
        app.setScreen(form);
        form.typeName(0, "Ann");
        form.teeOff();
        PlayingScreen playing = app.screens().playing();
        Game game = app.game();
        assertTrue(game.hasMovingObstacles());
        // The player looks at the windmill for half a second (the clock runs while a person aims), then aims.
        for (int frame = 0; frame < 30; frame++) playing.update(1.0 / 60);
        assertEquals(0.5, game.clock(), 1e-9);
        playing.showAim(3.5, 0, 0);
        playing.update(0);
        double clock = game.clock();
        PlayerState ball = game.player(game.currentPlayer());
        AimGuide atZero = AimGuide.preview(windmill, game.settings(), ball.x(), ball.y(), 3.5, 0, 0, AimGuide.FULL_SECONDS);
        float[] guide = null;
        for (int i = 0; i < 500; i++) {
            AimView aim = playing.aim();
            assertNotNull(aim, "the aim is shown");
            guide = aim.guide();
            if (guide != null && i > 20) break;
            Thread.sleep(10);
        }
        assertNotNull(guide, "the guide was worked out");
        // The release: the stroke the game plays, at the clock it stands at.
        assertEquals(clock, game.clock(), "the clock stood still while the test waited for the guide");
        app.play().hit(3.5, 0, 0);
        app.play().skipAnimation();
        playing.update(0);
        ShotRecord played = app.play().lastStroke();
        assertEquals(clock, played.clock(), 1e-12);
        float endX = guide[guide.length - 3], endY = guide[guide.length - 2];
        assertEquals(played.endX(), endX, 1e-5, "the guide ends where the ball stopped");
        assertEquals(played.endY(), endY, 1e-5);
        float zeroEnd = atZero.points()[atZero.points().length - 3];
        assertTrue(Math.abs(zeroEnd - played.endX()) > 1, "at clock 0 a blade stops this putt (ends at x = " + zeroEnd
                + "), so a guide at clock 0 would not show the stroke played (x = " + played.endX() + ")");
    }
}
