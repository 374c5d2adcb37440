package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.collision.CollisionScene;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The opening view of a hole shows the cup: on Meadowbrook's windmill hole the windmill stood
 * between the eye behind the tee and the cup, so a player could not see where to putt. Checked
 * with the collision geometry (an independent test of the line of sight: no point along it lies
 * within 2 cm of an obstacle's surface or under the ground), on every hole of the round.
 */
class OpeningViewTest {
    private static final float ASPECT = 16f / 9;

    /** Whether the straight line from the eye to the cup passes clear of every obstacle and above the ground. */
    private static boolean cupVisible(World w, Vector3f eye) {
        double hx = w.hole().position().x(), hy = w.hole().position().y(), hz = w.terrain().height(hx, hy) + 0.02;
        CollisionScene scene = w.obstacles();
        for (int i = 1; i < 400; i++) {
            double t = i / 400.0;
            double x = eye.x + t * (hx - eye.x), y = eye.y + t * (hy - eye.y), z = eye.z + t * (hz - eye.z);
            if (w.bounds().contains(x, y) && z < w.terrain().height(x, y)) return false;
            if (scene != null && scene.anyNear(x - 0.05, y - 0.05, x + 0.05, y + 0.05) && scene.clearance(x, y, z) < 0.02) {
                return false;
            }
        }
        return true;
    }

    @Test
    void theWindmillNoLongerHidesTheCupFromTheTee() throws Exception {
        Round round = RoundLoader.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "rounds",
                "meadowbrook-18.json"));
        World windmill = round.hole(2).world();
        assertTrue(windmill.course().name().toLowerCase().contains("windmill"), windmill.course().name());
        OrbitCamera before = OrbitCamera.behindBall(windmill.course(), windmill.terrain(), ASPECT);
        before.setClearance(CameraClearance.of(windmill.course(), windmill.terrain()::height));
        assertTrue(!cupVisible(windmill, before.eye()), "the plain view behind the ball looks at the windmill, not the cup");
        List<String> hidden = new ArrayList<>();
        for (int i = 0; i < round.size(); i++) {
            World w = round.hole(i).world();
            OrbitCamera cam = OrbitCamera.opening(w.course(), w.terrain(), ASPECT);
            if (!cupVisible(w, cam.eye())) hidden.add(w.course().name());
            cam.reset();
            assertTrue(cupVisible(w, cam.eye()) || hidden.contains(w.course().name()), "R brings the same view back");
        }
        assertTrue(hidden.isEmpty(), "holes whose cup the opening view does not show: " + hidden);
    }
}
