package minigolf.render;

import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The sky: clouds above the horizon in both qualities, none below it (needs xvfb-run). */
class SkyRenderTest {
    static final int W = 800, H = 450;

    static Pixels draw(RenderQuality quality) {
        Course course = TestCourses.flat();
        // Almost level (the lowest pitch the game allows), aimed a little above the ground: the upper
        // part of the image is sky up to about 18 degrees above the horizon.
        OrbitCamera cam = new OrbitCamera(new Vector3f(0, 0, 0.6f), (float) Math.toRadians(-90), OrbitCamera.MIN_PITCH, 3f);
        Path png = TestCourses.screenshotDir().resolve("sky-" + quality.name() + ".png");
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, quality)) {
            r.setBalls(List.of());
            off.bind();
            r.render(cam, W, H, 0f);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    static boolean cloud(Pixels p, int x, int y) {
        return p.r(x, y) > 200 && p.b(x, y) - p.r(x, y) < 25;
    }

    static boolean blue(Pixels p, int x, int y) {
        return p.b(x, y) - p.r(x, y) > 45;
    }

    @Test
    void cloudsAndBlueSkyShareTheTopOfTheImageInBothQualities() {
        for (RenderQuality q : new RenderQuality[]{RenderQuality.HIGH, RenderQuality.SOFTWARE}) {
            Pixels p = draw(q);
            int clouds = 0, sky = 0, total = 0;
            for (int y = 0; y < H / 8; y++) {
                for (int x = 0; x < W; x++) {
                    total++;
                    if (cloud(p, x, y)) clouds++;
                    if (blue(p, x, y)) sky++;
                }
            }
            assertTrue(clouds > total / 50, q.name() + ": only " + clouds + " of " + total + " cloud pixels; top left " + p.describe(0, 0));
            assertTrue(sky > total / 10, q.name() + ": only " + sky + " of " + total + " blue pixels; top left " + p.describe(0, 0));
        }
    }
}
