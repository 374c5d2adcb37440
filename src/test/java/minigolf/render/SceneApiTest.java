package minigolf.render;

import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The renderer's game-facing API: coloured balls, the aiming arrow, the minimap. Needs xvfb-run. */
class SceneApiTest {
    static final int W = 800, H = 500;

    private static Pixels draw(String name, OrbitCamera cam, java.util.function.Consumer<SceneRenderer> setup,
                               java.util.function.Consumer<SceneRenderer> after) {
        Course course = TestCourses.lake();
        Path png = TestCourses.screenshotDir().resolve(name);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.LAKE, TerrainMesh.ColorMode.GREEN)) {
            setup.accept(r);
            off.bind();
            r.render(cam, W, H, 0f);
            after.accept(r);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    private static OrbitCamera top() {
        return OrbitCamera.topDown(TestCourses.lake(), TestCourses.LAKE, new Vector3f(0, 0, 0), (float) W / H);
    }

    @Test
    void ballsAreDrawnWhereAndInTheColourGiven() {
        OrbitCamera cam = top();
        float x = -2.5f, y = 1.5f, z = (float) TestCourses.LAKE.height(x, y);
        Pixels px = draw("api-balls.png", cam, r -> r.setBalls(List.of(new BallView(x, y, z, 1f, 0.1f, 0.1f))), r -> {
        });
        float[] p = cam.project(new Vector3f(x, y, z + (float) ObjectsPass.visualBallRadius()), W, H);
        int bx = Math.round(p[0]), by = Math.round(p[1]);
        assertTrue(px.r(bx, by) > 150 && px.g(bx, by) < 90 && px.b(bx, by) < 90, "no red ball: " + px.describe(bx, by));
        // The default white ball at the start is gone.
        Course c = TestCourses.lake();
        float[] s = cam.project(new Vector3f((float) c.start().x(), (float) c.start().y(),
                (float) TestCourses.LAKE.height(c.start().x(), c.start().y())), W, H);
        assertFalse(px.isNearWhite(Math.round(s[0]), Math.round(s[1])), "the default ball is still drawn: "
                + px.describe(Math.round(s[0]), Math.round(s[1])));
    }

    @Test
    void aimArrowGrowsAndReddensWithPower() {
        OrbitCamera cam = top();
        float x = -3f, y = -1.5f, z = (float) TestCourses.LAKE.height(x, y);
        for (float power : new float[]{0f, 1f}) {
            Pixels px = draw("api-aim-" + (int) power + ".png", cam, r -> {
                r.setBalls(List.of(BallView.white(x, y, z)));
                r.setAim(new AimView(x, y, z, 0f, 2f, power)); // +y, not unit length
            }, r -> {
            });
            double length = ObjectsPass.visualBallRadius() * 1.3 + ObjectsPass.ARROW_MIN_LENGTH + ObjectsPass.ARROW_POWER_LENGTH * power;
            // Along the shaft (before the head) the colour is the power colour; beyond the tip it is grass.
            float[] mid = cam.project(new Vector3f(x, (float) (y + 0.5 * length), z), W, H);
            float[] beyond = cam.project(new Vector3f(x, (float) (y + length + 0.15), z), W, H);
            int mx = Math.round(mid[0]), my = Math.round(mid[1]);
            if (power == 0f) {
                assertTrue(px.g(mx, my) > 150 && px.r(mx, my) < 120, "no green arrow at no power: " + px.describe(mx, my));
            } else {
                assertTrue(px.r(mx, my) > 170 && px.g(mx, my) < 90, "no red arrow at full power: " + px.describe(mx, my));
            }
            int ex = Math.round(beyond[0]), ey = Math.round(beyond[1]);
            assertTrue(px.g(ex, ey) > px.r(ex, ey) && px.r(ex, ey) < 150, "arrow reaches past its length: " + px.describe(ex, ey));
        }
    }

    @Test
    void minimapShowsTheCourseFromAboveInItsSquare() {
        OrbitCamera cam = OrbitCamera.behindBall(TestCourses.lake(), TestCourses.LAKE, (float) W / H);
        int size = 200, left = W - size - 10, topY = 10;
        Pixels px = draw("api-minimap.png", cam, r -> r.setBalls(List.of(new BallView(-2f, 2f,
                (float) TestCourses.LAKE.height(-2, 2), 1f, 0.1f, 0.1f))), r -> r.renderMinimap(left, topY, size, W, H));
        // The bounds -5..5 (padded 2%) map onto the inner square; the map centre is the pond's centre.
        int cx = left + size / 2, cy = topY + size / 2;
        assertTrue(px.isWater(cx, cy), "no water at the minimap's centre: " + px.describe(cx, cy));
        // The red ball at (-2, 2): left of and above the centre (y up on the map).
        double pixelsPerMetre = (size - 2 * 2) / 10.4;
        int bx = (int) Math.round(cx - 2 * pixelsPerMetre), by = (int) Math.round(cy - 2 * pixelsPerMetre);
        assertTrue(px.r(bx, by) > 150 && px.g(bx, by) < 90, "no red ball on the minimap: " + px.describe(bx, by));
        // The hole at (3.3, 3.0): a dark cup.
        int hx = (int) Math.round(cx + 3.3 * pixelsPerMetre), hy = (int) Math.round(cy - 3.0 * pixelsPerMetre);
        assertTrue(px.r(hx, hy) < 60 && px.g(hx, hy) < 60, "no hole on the minimap: " + px.describe(hx, hy));
        // Outside the square the main view is untouched: the border is dark, left of it is the scene.
        assertTrue(px.r(left + 1, cy) < 40, "no border: " + px.describe(left + 1, cy));
        assertFalse(px.r(left - 3, cy) < 40 && px.g(left - 3, cy) < 40, "main view cleared: " + px.describe(left - 3, cy));
    }
}
