package minigolf.render;

import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Water reflection and refraction (needs xvfb-run). */
class WaterTest {
    static final int W = 800, H = 500;

    /** A low camera on the near side of the pond looking across it at a red ball on its far bank. */
    static OrbitCamera lowOverThePond() {
        return new OrbitCamera(new Vector3f(0.0f, 1.05f, 0.0f), (float) Math.toRadians(-90), (float) Math.toRadians(9), 2.6f);
    }

    static Pixels draw(String name, boolean reflections, OrbitCamera cam, float time) {
        return draw(name, reflections, cam, time, RenderQuality.HIGH);
    }

    static Pixels draw(String name, boolean reflections, OrbitCamera cam, float time, RenderQuality quality) {
        Course course = TestCourses.lake();
        Path png = TestCourses.screenshotDir().resolve(name);
        float y = 1.05f;
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.LAKE, TerrainMesh.ColorMode.GREEN, quality)) {
            r.setWaterReflections(reflections);
            r.setBalls(List.of(new BallView(0f, y, (float) TestCourses.LAKE.height(0, y), 1f, 0.05f, 0.05f)));
            off.bind();
            r.render(cam, W, H, time);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    @Test
    void theRedBallIsMirroredInThePondOnlyWithReflections() {
        redBallMirrored(RenderQuality.HIGH);
    }

    /** The software quality (coarser terrain, smaller targets, sky drawn last) still mirrors the ball. */
    @Test
    void theSoftwareQualityMirrorsTheBallToo() {
        redBallMirrored(RenderQuality.SOFTWARE);
    }

    private static void redBallMirrored(RenderQuality quality) {
        OrbitCamera cam = lowOverThePond();
        Pixels on = draw("water-reflection-on-" + quality.name() + ".png", true, cam, 0f, quality);
        Pixels off = draw("water-reflection-off-" + quality.name() + ".png", false, cam, 0f, quality);
        // The mirror image of the ball's centre, (0, 1.05, -(h + r)), is where the reflection shows.
        float r = (float) ObjectsPass.visualBallRadius();
        float z = (float) TestCourses.LAKE.height(0, 1.05) + r;
        float[] mirror = cam.project(new Vector3f(0f, 1.05f, -z), W, H);
        int mx = Math.round(mirror[0]), my = Math.round(mirror[1]);
        assertTrue(off.isWater(mx, my), "no water under the ball's mirror image without reflections: " + off.describe(mx, my));
        int redderOn = on.r(mx, my) - on.b(mx, my), redderOff = off.r(mx, my) - off.b(mx, my);
        assertTrue(redderOn > redderOff + 30, "the mirror image is not red: with " + on.describe(mx, my)
                + ", without " + off.describe(mx, my));
    }

    @Test
    void ripplesMoveWithTime() {
        OrbitCamera cam = lowOverThePond();
        Pixels a = draw("water-t0.png", true, cam, 0f);
        Pixels b = draw("water-t1.png", true, cam, 1.5f);
        float[] c = cam.project(new Vector3f(0, 0, 0), W, H);
        int changed = 0, total = 0;
        for (int y = Math.round(c[1]) - 15; y <= Math.round(c[1]) + 15; y++) {
            for (int x = Math.round(c[0]) - 80; x <= Math.round(c[0]) + 80; x++) {
                total++;
                if (Math.abs(a.r(x, y) - b.r(x, y)) + Math.abs(a.g(x, y) - b.g(x, y)) + Math.abs(a.b(x, y) - b.b(x, y)) > 6) changed++;
            }
        }
        assertTrue(changed > total / 10, "the water did not move: " + changed + " of " + total + " pixels changed");
    }
}
