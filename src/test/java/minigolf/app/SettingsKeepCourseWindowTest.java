package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Obstacle;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;

/**
 * ESC, Settings, Apply in the middle of a hole (nothing changed) leaves the course as it was: the
 * obstacles drawn (scene and minimap share the renderer's obstacle pass) and the obstacles the ball
 * collides with, in the game being played and in the next game on the same course. Before the fix
 * Apply rebuilt the course without its walls, rails and boxes.
 */
@minigolf.render.NeedsDisplay
class SettingsKeepCourseWindowTest {
    @TempDir
    Path dir;

    private record Seen(List<Obstacle> drawn, List<Obstacle> inCourse, boolean collides, double[] wallShotEnd) {
    }

    /** A putt along the tee's row: on both courses it meets a wall or a rail. */
    private static double[] wallShot(World w) {
        ShotResult r = new Simulator(w, SimulationSettings.DEFAULT).simulate(w.course().start().x(), w.course().start().y(),
                3.2, 0.4);
        return new double[]{r.endX(), r.endY()};
    }

    private static Seen seen(GameApp app) {
        World played = app.game().world();
        return new Seen(app.scene().renderer().obstaclesPass().obstacles(), app.world().course().obstacles(),
                played.obstacles() != null, wallShot(played));
    }

    @ParameterizedTest
    @ValueSource(strings = {"courses/walled.json", "courses/holes/07-volcano.json"})
    void applyingSettingsMidHoleKeepsEveryWallRailAndBox(String course) throws Exception {
        Path file = Path.of(System.getProperty("minigolf.projectDir", "."), course);
        World world = World.load(file);
        int obstacles = world.course().obstacles().size();
        double[] expected = wallShot(world);
        Seen[] seen = new Seen[3];
        GameApp app = new GameApp(world, new GameApp.Options(file, null, 40, List.of(Player.human("Ann")), List.of(), 1,
                new SettingsStore(dir.resolve("config")), true, false));
        app.onLoopPass((pass, window) -> {
            switch (pass) {
                case 4 -> seen[0] = seen(app);
                case 5 -> app.openSettings();
                case 8 -> app.screens().settings().apply(); // "Apply" with nothing changed
                case 12 -> seen[1] = seen(app);
                case 13 -> app.startGame(List.of(Player.human("Ann"))); // the next game on this course
                case 16 -> seen[2] = seen(app);
                default -> { }
            }
        });
        app.run();
        assertSame(app.screens().playing(), app.screen(), "Apply went back to the hole");
        String[] when = {"before Apply", "after Apply", "in the next game"};
        for (int i = 0; i < seen.length; i++) {
            Seen s = seen[i];
            assertNotNull(s, when[i]);
            assertEquals(obstacles, s.drawn().size(), "obstacles drawn " + when[i]);
            assertEquals(world.course().obstacles(), s.inCourse(), "the course's obstacles " + when[i]);
            assertEquals(true, s.collides(), "the ball collides with them " + when[i]);
            assertEquals(expected[0], s.wallShotEnd()[0], 1e-12, "a putt into a wall ends where it did " + when[i]);
            assertEquals(expected[1], s.wallShotEnd()[1], 1e-12, "a putt into a wall ends where it did " + when[i]);
        }
    }
}
