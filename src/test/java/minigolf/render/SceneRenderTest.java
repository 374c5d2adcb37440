package minigolf.render;

import minigolf.app.GameWindow;
import minigolf.course.Course;
import minigolf.terrain.Terrain;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/** Renders courses off-screen (needs a display: run under xvfb-run) and checks the pictures. */
class SceneRenderTest {
    static final int W = 960, H = 600;

    private static Path shot(String name, Course course, Terrain terrain, OrbitCamera camera) {
        Path png = TestCourses.screenshotDir().resolve(name);
        GameWindow.screenshot(course, terrain, camera, TerrainMesh.ColorMode.GREEN, W, H, png);
        assertTrue(Files.exists(png), "no screenshot written at " + png);
        return png;
    }

    @Test
    void lakeSeenFromAboveShowsWaterAroundTheOrigin() {
        Course course = TestCourses.lake();
        OrbitCamera cam = OrbitCamera.topDown(course, TestCourses.LAKE, new Vector3f(0, 0, 0), (float) W / H);
        Pixels px = Pixels.read(shot("lake-top.png", course, TestCourses.LAKE, cam));
        assertEquals(W, px.width());
        assertEquals(H, px.height());
        float[] o = cam.project(new Vector3f(0, 0, 0), W, H);
        int cx = Math.round(o[0]), cy = Math.round(o[1]), water = 0, total = 0;
        for (int y = cy - 10; y <= cy + 10; y++) {
            for (int x = cx - 10; x <= cx + 10; x++) {
                total++;
                if (px.isWater(x, y)) water++;
            }
        }
        assertTrue(water > total * 0.9, water + " of " + total + " pixels around the origin look like water; centre "
                + px.describe(cx, cy));
        // Far from the pond (a metre and more inland) it is grass, not water.
        float[] land = cam.project(new Vector3f(-2.5f, 0, (float) TestCourses.LAKE.height(-2.5, 0)), W, H);
        int lx = Math.round(land[0]), ly = Math.round(land[1]);
        assertFalse(px.isWater(lx, ly), "grass looks like water: " + px.describe(lx, ly));
        assertTrue(px.g(lx, ly) > px.r(lx, ly) && px.g(lx, ly) > px.b(lx, ly), "grass is not green: " + px.describe(lx, ly));
    }

    /** An extra hole (a course may have several) is drawn as a cup: dark where the same spot is grass without it. */
    @Test
    void anExtraHoleIsDrawnAsACup() {
        Course one = TestCourses.flat();
        Course two = one.withHoles(one.hole(), java.util.List.of(
                new minigolf.course.Hole(new minigolf.course.Vec2(-1, 2), 0.25, minigolf.course.HoleRule.REST, null)));
        OrbitCamera cam = OrbitCamera.topDown(one, TestCourses.FLAT, new Vector3f(0, 0, 0.1f), (float) W / H);
        float[] at = cam.project(new Vector3f(-1, 2, 0.1f), W, H);
        int x = Math.round(at[0]), y = Math.round(at[1]);
        Pixels without = Pixels.read(shot("one-hole-top.png", one, TestCourses.FLAT, cam));
        Pixels with = Pixels.read(shot("extra-hole-top.png", two, TestCourses.FLAT, cam));
        assertTrue(without.g(x, y) > 80, "grass without the extra hole: " + without.describe(x, y));
        assertTrue(with.r(x, y) + with.g(x, y) + with.b(x, y) < 100, "a dark cup at the extra hole: " + with.describe(x, y));
    }

    /** A breakable brick standing is drawn (a box where the same spot is grass without it). */
    @Test
    void aStandingBrickIsDrawn() {
        Course none = TestCourses.flat();
        Course brick = none.withBricks(java.util.List.of(new minigolf.course.Brick(new minigolf.course.Vec3(-1.25, 1.75, -0.05),
                new minigolf.course.Vec3(-0.75, 2.25, 0.3), 4, 0.9)));
        OrbitCamera cam = OrbitCamera.topDown(none, TestCourses.FLAT, new Vector3f(0, 0, 0.1f), (float) W / H);
        float[] at = cam.project(new Vector3f(-1, 2, 0.3f), W, H);
        int x = Math.round(at[0]), y = Math.round(at[1]);
        Pixels without = Pixels.read(shot("no-brick-top.png", none, TestCourses.FLAT, cam));
        Pixels with = Pixels.read(shot("brick-top.png", brick, TestCourses.FLAT, cam));
        assertTrue(without.g(x, y) > without.r(x, y) && without.g(x, y) > without.b(x, y), "grass without the brick: " + without.describe(x, y));
        assertFalse(with.g(x, y) > with.r(x, y) + 10 && with.g(x, y) > with.b(x, y) + 10, "not grass where the brick stands: " + with.describe(x, y));
    }

    @Test
    void flatCourseShowsNoWater() {
        Course course = TestCourses.flat();
        OrbitCamera cam = OrbitCamera.topDown(course, TestCourses.FLAT, new Vector3f(0, 0, 0.1f), (float) W / H);
        Pixels px = Pixels.read(shot("flat-top.png", course, TestCourses.FLAT, cam));
        int water = 0;
        String first = null;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (px.isWater(x, y)) {
                    water++;
                    if (first == null) first = px.describe(x, y);
                }
            }
        }
        assertEquals(0, water, "water-coloured pixels on a dry course, first " + first);
    }

    @Test
    void openingViewShowsTheWhiteBallBehindWhichTheCameraStands() {
        Course course = TestCourses.lake();
        OrbitCamera cam = OrbitCamera.behindBall(course, TestCourses.LAKE, (float) W / H);
        Path png = shot("lake.png", course, TestCourses.LAKE, null); // null: the same opening view
        Pixels px = Pixels.read(png);
        Vector3f ball = new Vector3f((float) course.start().x(), (float) course.start().y(),
                (float) (TestCourses.LAKE.height(course.start().x(), course.start().y()) + ObjectsPass.visualBallRadius()));
        float[] p = cam.project(ball, W, H);
        int bx = Math.round(p[0]), by = Math.round(p[1]), white = 0;
        for (int y = by - 1; y <= by + 1; y++) {
            for (int x = bx - 1; x <= bx + 1; x++) {
                if (px.isNearWhite(x, y)) white++;
            }
        }
        assertTrue(white >= 7, "the ball is not visible: " + white + "/9 near-white pixels, centre " + px.describe(bx, by));
        // A few ball radii beside it, it is grass again.
        assertFalse(px.isNearWhite(bx + 25, by), "white beside the ball: " + px.describe(bx + 25, by));
        // The hole is ahead: higher up in the picture than the ball.
        float[] hole = cam.project(new Vector3f((float) course.hole().position().x(), (float) course.hole().position().y(),
                (float) TestCourses.LAKE.height(course.hole().position().x(), course.hole().position().y())), W, H);
        assertTrue(hole[1] < by - 50, "the hole is not ahead of the ball on screen: hole y " + hole[1] + ", ball y " + by);
    }

    @Test
    void heightMapColouringRendersToo() {
        Course course = TestCourses.lake();
        Path png = TestCourses.screenshotDir().resolve("lake-heightmap.png");
        GameWindow.screenshot(course, TestCourses.LAKE, null, TerrainMesh.ColorMode.HEIGHT_MAP, W, H, png);
        Pixels px = Pixels.read(png);
        OrbitCamera cam = OrbitCamera.behindBall(course, TestCourses.LAKE, (float) W / H);
        float[] corner = cam.project(new Vector3f(4.9f, 4.9f, (float) TestCourses.LAKE.height(4.9, 4.9)), W, H);
        int x = Math.round(corner[0]), y = Math.round(corner[1]) + 3;
        // The highest ground (the far corner) is light: the top of the ramp is white.
        assertTrue(px.r(x, y) > 170 && px.g(x, y) > 170 && px.b(x, y) > 170, "far corner not light: " + px.describe(x, y));
    }
}
