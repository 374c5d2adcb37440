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

    /**
     * The software quality draws no images for the water: it mirrors the sky's gradient, not the scene,
     * so the red ball's mirror image is not there (the price of the cheaper water, docs/rendering.md).
     */
    @Test
    void theSoftwareQualityMirrorsTheSkyNotTheBall() {
        OrbitCamera cam = lowOverThePond();
        Pixels on = draw("water-sky-mirror-software.png", true, cam, 0f, RenderQuality.SOFTWARE);
        Pixels high = draw("water-reflection-on-high-for-software.png", true, cam, 0f, RenderQuality.HIGH);
        float r = (float) ObjectsPass.visualBallRadius();
        float z = (float) TestCourses.LAKE.height(0, 1.05) + r;
        float[] mirror = cam.project(new Vector3f(0f, 1.05f, -z), W, H);
        int mx = Math.round(mirror[0]), my = Math.round(mirror[1]);
        int redderSoftware = on.r(mx, my) - on.b(mx, my), redderHigh = high.r(mx, my) - high.b(mx, my);
        assertTrue(redderSoftware + 30 < redderHigh, "software " + on.describe(mx, my) + ", high " + high.describe(mx, my));
        assertTrue(on.b(mx, my) > on.r(mx, my), "not the sky's blue: " + on.describe(mx, my));
    }

    /**
     * Seen from above, where the water shows mostly the bed, the software quality's water (the bed
     * already drawn, tinted by blending) looks as the high quality's (the bed's image, tinted in the
     * shader): the same mean colour within 12 levels from the deep middle to the shallows, while
     * the plain colours that stand in without reflections are further off.
     */
    @Test
    void fromAboveTheSoftwareWaterShowsTheBedAsTheHighQualitysDoes() {
        OrbitCamera cam = new OrbitCamera(new Vector3f(0.4f, 0f, 0f), (float) Math.toRadians(-90), (float) Math.toRadians(75), 2.2f);
        Pixels software = draw("water-above-software.png", true, cam, 0f, RenderQuality.SOFTWARE);
        Pixels high = draw("water-above-high.png", true, cam, 0f, RenderQuality.HIGH);
        Pixels plain = draw("water-above-plain.png", false, cam, 0f, RenderQuality.SOFTWARE);
        int plainOff = 0;
        for (float x : new float[]{0f, 0.4f, 0.75f}) {
            float[] p = cam.project(new Vector3f(x, 0f, 0f), W, H);
            int[] s = mean(software, p), h = mean(high, p), f = mean(plain, p);
            for (int c = 0; c < 3; c++) {
                assertEquals(h[c], s[c], 12, "channel " + c + " at x = " + x + ": software " + java.util.Arrays.toString(s)
                        + ", high " + java.util.Arrays.toString(h));
                plainOff = Math.max(plainOff, Math.abs(f[c] - h[c]));
            }
        }
        assertTrue(plainOff > 12, "the plain water is as close: " + plainOff); // measured: 17
    }

    /** The mean colour of the 9 x 9 pixels round a projected point. */
    private static int[] mean(Pixels px, float[] at) {
        int cx = Math.round(at[0]), cy = Math.round(at[1]);
        int[] sum = new int[3];
        for (int y = cy - 4; y <= cy + 4; y++) {
            for (int x = cx - 4; x <= cx + 4; x++) {
                sum[0] += px.r(x, y);
                sum[1] += px.g(x, y);
                sum[2] += px.b(x, y);
            }
        }
        return new int[]{sum[0] / 81, sum[1] / 81, sum[2] / 81};
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
