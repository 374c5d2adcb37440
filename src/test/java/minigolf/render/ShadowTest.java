package minigolf.render;

import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Sun shadows (needs xvfb-run). */
class ShadowTest {
    static final int W = 800, H = 500;
    static final float BX = -2.5f, BY = -1.0f;

    static Pixels draw(String name, boolean shadows, OrbitCamera cam) {
        return draw(name, shadows, cam, RenderQuality.HIGH);
    }

    static Pixels draw(String name, boolean shadows, OrbitCamera cam, RenderQuality quality) {
        Course course = TestCourses.flat();
        Path png = TestCourses.screenshotDir().resolve(name);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, quality)) {
            r.setShadows(shadows);
            r.setBalls(List.of(BallView.white(BX, BY, 0.1)));
            off.bind();
            r.render(cam, W, H, 0f);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    static int luminance(Pixels p, int x, int y) {
        return (p.r(x, y) * 3 + p.g(x, y) * 6 + p.b(x, y)) / 10;
    }

    @Test
    void theBallShadowsTheGroundAwayFromTheSunAndNotTowardsIt() {
        ballShadowAwayFromTheSun(RenderQuality.HIGH);
    }

    /** The software quality's per-vertex-lit terrain keeps the same shadows, without acne. */
    @Test
    void theSoftwareQualityShadowsTheSameWay() {
        ballShadowAwayFromTheSun(RenderQuality.SOFTWARE);
    }

    private static void ballShadowAwayFromTheSun(RenderQuality quality) {
        // From above (pitch 89 degrees), close to the ball.
        OrbitCamera cam = new OrbitCamera(new Vector3f(BX, BY, 0.1f), (float) Math.toRadians(-90), (float) Math.toRadians(89), 1.2f);
        Pixels on = draw("shadow-on-" + quality.name() + ".png", true, cam, quality);
        Pixels off = draw("shadow-off-" + quality.name() + ".png", false, cam, quality);
        Vector3f sun = FrameContext.Sun.afternoon().direction();
        float r = (float) ObjectsPass.visualBallRadius();
        // The ball's centre is r above the ground; its shadow's centre lies r * horizontal/vertical beyond the contact point.
        float hx = -sun.x, hy = -sun.y, hl = (float) Math.hypot(hx, hy), reach = r * hl / sun.z;
        float sx = BX + hx / hl * (reach + 0.6f * r), sy = BY + hy / hl * (reach + 0.6f * r);
        float[] shade = cam.project(new Vector3f(sx, sy, 0.1f), W, H);
        int x = Math.round(shade[0]), y = Math.round(shade[1]);
        assertTrue(luminance(on, x, y) < 0.75 * luminance(off, x, y),
                "no shadow beside the ball: with " + on.describe(x, y) + ", without " + off.describe(x, y));
        // On the sunny side of the ball the ground is as bright as without shadows (no acne).
        float[] lit = cam.project(new Vector3f(BX - hx / hl * 2 * r, BY - hy / hl * 2 * r, 0.1f), W, H);
        int lx = Math.round(lit[0]), ly = Math.round(lit[1]);
        assertTrue(Math.abs(luminance(on, lx, ly) - luminance(off, lx, ly)) <= 3,
                "the sunny side changed: with " + on.describe(lx, ly) + ", without " + off.describe(lx, ly));
        // Open ground far from the ball: shadows change nothing anywhere in a 40 x 40 block (no acne).
        for (int yy = 20; yy < 60; yy++) {
            for (int xx = 20; xx < 60; xx++) {
                assertTrue(Math.abs(luminance(on, xx, yy) - luminance(off, xx, yy)) <= 3,
                        "acne on open ground: with " + on.describe(xx, yy) + ", without " + off.describe(xx, yy));
            }
        }
    }
}
