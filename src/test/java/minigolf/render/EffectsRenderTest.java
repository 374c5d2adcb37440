package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/** The celebration on holing draws (pixels change round the cup) and ends (the picture is as before). Off-screen. */
class EffectsRenderTest {
    static final int W = 640, H = 400;

    private static Pixels draw(String name, OrbitCamera cam, Particles effects) {
        Course course = TestCourses.lake();
        Path png = TestCourses.screenshotDir().resolve(name);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.LAKE, TerrainMesh.ColorMode.GREEN)) {
            r.setEffects(effects.mesh());
            off.bind();
            r.render(cam, W, H, 0f);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    @Test
    void confettiDrawsRoundTheCupAndEnds() {
        Course course = TestCourses.lake();
        double hx = course.hole().position().x(), hy = course.hole().position().y();
        double hz = TestCourses.LAKE.height(hx, hy);
        // Close to the cup, as the game's camera is after a putt.
        OrbitCamera cam = new OrbitCamera(new Vector3f((float) hx, (float) hy, (float) hz), -2.5f, (float) Math.toRadians(40), 2.5f);
        Particles effects = new Particles();
        Pixels before = draw("effects-before.png", cam, effects);

        effects.burst(Particles.Kind.ACE_CONFETTI, hx, hy, hz, 5);
        for (int i = 0; i < 20; i++) effects.update(1 / 60.0);
        Pixels during = draw("effects-confetti.png", cam, effects);
        float[] cup = cam.project(new Vector3f((float) hx, (float) hy, (float) hz), W, H);
        int changed = 0, coloured = 0;
        int r = 150;
        for (int y = Math.max(0, (int) cup[1] - r); y < Math.min(H, (int) cup[1] + r); y++) {
            for (int x = Math.max(0, (int) cup[0] - r); x < Math.min(W, (int) cup[0] + r); x++) {
                int d = Math.abs(during.r(x, y) - before.r(x, y)) + Math.abs(during.g(x, y) - before.g(x, y))
                        + Math.abs(during.b(x, y) - before.b(x, y));
                if (d > 60) changed++;
                // Confetti red, blue, violet or orange where the course is green grass.
                if (during.r(x, y) > during.g(x, y) + 40 || during.b(x, y) > during.g(x, y) + 40) coloured++;
            }
        }
        assertTrue(changed > 300, "pixels changed round the cup: " + changed);
        assertTrue(coloured > 100, "confetti colours round the cup: " + coloured);

        for (int i = 0; i < 60 * 4; i++) effects.update(1 / 60.0);
        assertFalse(effects.isActive(), "the celebration ends by itself");
        Pixels after = draw("effects-after.png", cam, effects);
        int differ = 0;
        for (int y = 0; y < H; y++) for (int x = 0; x < W; x++) if (after.rgb()[y * W + x] != before.rgb()[y * W + x]) differ++;
        assertEquals(0, differ, "the picture is as before the burst");
    }
}
