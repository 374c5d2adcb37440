package minigolf.render;

import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11.glGetError;

/** Obstacles on screen, in the sun's shadow map and replaced live; a ball in the air (needs xvfb-run). */
class ObstacleRenderTest {
    static final int W = 800, H = 500;
    /** A wall along y at x = 0, 0.1 thick and 0.3 high, on the flat test course (h = 0.1). */
    static final Obstacle WALL = new Obstacle.Wall(new Vec2(0, -1.5), new Vec2(0, 1.5), 0.1, 0.3, 0.7);
    static final OrbitCamera ABOVE = new OrbitCamera(new Vector3f(0, 0, 0.1f), (float) Math.toRadians(-90),
            (float) Math.toRadians(89), 5f);

    static int luminance(Pixels p, int x, int y) {
        return (p.r(x, y) * 3 + p.g(x, y) * 6 + p.b(x, y)) / 10;
    }

    static int[] at(float x, float y, float z) {
        float[] s = ABOVE.project(new Vector3f(x, y, z), W, H);
        return new int[]{Math.round(s[0]), Math.round(s[1])};
    }

    static boolean grassy(Pixels p, int[] xy) {
        return p.g(xy[0], xy[1]) > p.r(xy[0], xy[1]) + 20;
    }

    static boolean wooden(Pixels p, int[] xy) {
        return p.r(xy[0], xy[1]) > p.g(xy[0], xy[1]) + 20 && p.g(xy[0], xy[1]) > p.b(xy[0], xy[1]);
    }

    static Pixels shot(Offscreen off, SceneRenderer r, String name) {
        off.bind();
        r.render(ABOVE, W, H, 0f);
        assertEquals(GL_NO_ERROR, glGetError(), name);
        Path png = TestCourses.screenshotDir().resolve(name);
        off.savePng(png);
        return Pixels.read(png);
    }

    @Test
    void setObstaclesAddsAndRemovesTheWallWherePhysicsHasIt() {
        Course course = TestCourses.flat();
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)) {
            r.setBalls(List.of());
            int[] wallTop = at(0, 0.5f, 0.4f), beside = at(-0.6f, 0.5f, 0.1f), farAway = at(1.2f, -0.8f, 0.1f);
            Pixels none = shot(off, r, "obstacles-none.png");
            assertTrue(grassy(none, wallTop), "grass before the wall: " + none.describe(wallTop[0], wallTop[1]));

            r.setObstacles(List.of(WALL));
            // The world's rails (Meadowbrook's: wood with a rounded top, RailShapes) inside the physics' slab.
            assertEquals(ObstacleMeshes.build(List.of(WALL), TestCourses.FLAT::height, m -> null, ObstacleMeshes.CrownStyle.COURSE,
                    ObstacleMeshes.Style.of(minigolf.theme.Themes.MEADOWBROOK)).solid().triangleCount(), r.obstaclesPass().solidTriangles());
            Pixels with = shot(off, r, "obstacles-wall.png");
            assertTrue(wooden(with, wallTop), "the wall's top: " + with.describe(wallTop[0], wallTop[1]));
            assertTrue(wooden(with, at(0, -1.3f, 0.4f)), "the wall's far end");
            assertTrue(grassy(with, at(0, 1.75f, 0.1f)), "past the wall's end (1.5 + 0.05) is grass");
            assertTrue(grassy(with, beside) && grassy(with, farAway), "no wall where there is none");
            assertEquals(none.rgb()[beside[1] * W + beside[0]], with.rgb()[beside[1] * W + beside[0]], "the sunny side is untouched");

            r.setObstacles(List.of());
            assertEquals(0, r.obstaclesPass().solidTriangles());
            Pixels removed = shot(off, r, "obstacles-removed.png");
            assertTrue(grassy(removed, wallTop), "grass again after removing: " + removed.describe(wallTop[0], wallTop[1]));
        }
    }

    @Test
    void aWallCastsItsShadowAwayFromTheSun() {
        Course course = TestCourses.flat().withObstacles(List.of(WALL));
        Vector3f sun = FrameContext.Sun.afternoon().direction();
        // The top edge (x = 0.05, z = 0.4) falls onto the ground 0.3 / sun.z along the sun's horizontal direction, backwards.
        float reach = 0.3f / sun.z;
        float shadowX = 0.05f - sun.x * reach * 0.5f, shadowY = 0.2f - sun.y * reach * 0.5f;
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)) {
            r.setBalls(List.of());
            r.setShadows(true);
            Pixels lit = shot(off, r, "wall-shadow-on.png");
            r.setShadows(false);
            Pixels flat = shot(off, r, "wall-shadow-off.png");
            int[] s = at(shadowX, shadowY, 0.1f);
            assertTrue(luminance(lit, s[0], s[1]) < 0.75 * luminance(flat, s[0], s[1]),
                    "no shadow behind the wall: with " + lit.describe(s[0], s[1]) + ", without " + flat.describe(s[0], s[1]));
            int[] far = at(0.05f - sun.x * reach * 1.6f, 0.2f - sun.y * reach * 1.6f, 0.1f);
            assertTrue(Math.abs(luminance(lit, far[0], far[1]) - luminance(flat, far[0], far[1])) <= 3,
                    "the shadow ends where the wall's top projects: " + lit.describe(far[0], far[1]));
            int[] sunny = at(-0.3f, 0.2f, 0.1f);
            assertTrue(Math.abs(luminance(lit, sunny[0], sunny[1]) - luminance(flat, sunny[0], sunny[1])) <= 3,
                    "the sunny side changed: " + lit.describe(sunny[0], sunny[1]));
        }
    }

    @Test
    void aBallInTheAirIsDrawnThereWithItsShadowOnTheGroundBelowAlongTheSun() {
        Course course = TestCourses.flat();
        float bx = 0.8f, by = -0.4f, ground = 0.1f, z = ground + 0.5f;
        Vector3f sun = FrameContext.Sun.afternoon().direction();
        float rad = (float) ObjectsPass.visualBallRadius();
        float t = (z + rad - ground) / sun.z; // from the ball's centre down the sun's ray to the ground
        float sx = bx - sun.x * t, sy = by - sun.y * t;
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)) {
            r.setBalls(List.of(new BallView(bx, by, z, 1f, 1f, 1f)));
            Pixels air = shot(off, r, "ball-in-air.png");
            r.setShadows(false);
            Pixels noShadow = shot(off, r, "ball-in-air-no-shadow.png");
            int[] ball = at(bx, by, z + rad);
            assertTrue(air.isNearWhite(ball[0], ball[1]), "the ball in the air: " + air.describe(ball[0], ball[1]));
            int[] shade = at(sx, sy, ground);
            assertTrue(luminance(air, shade[0], shade[1]) < 0.75 * luminance(noShadow, shade[0], shade[1]),
                    "no shadow 0.5 m down the sun's ray: " + air.describe(shade[0], shade[1]));
            // A resting ball's shadow would hug its contact point; this one leaves the ground there in the sun.
            int[] halfway = at(bx - sun.x * t * 0.45f, by - sun.y * t * 0.45f, ground);
            assertTrue(Math.abs(luminance(air, halfway[0], halfway[1]) - luminance(noShadow, halfway[0], halfway[1])) <= 3,
                    "ground between the ball and its shadow is lit: " + air.describe(halfway[0], halfway[1]));
        }
    }

    @Test
    void aTallObstacleAddedLaterStillCastsAShadow() {
        Course course = TestCourses.flat();
        // A 4 m tower: higher than the shadow map was first fitted to (flag top + headroom), so it is refitted.
        Obstacle tower = new Obstacle.Box(new Vec3(-0.2, -0.2, 0.1), new Vec3(0.2, 0.2, 4.1), 0, 0.7);
        Vector3f sun = FrameContext.Sun.afternoon().direction();
        float t = 3.6f / sun.z; // the tower's shadow at 3.6 m up lands here
        float sx = -sun.x * t, sy = -sun.y * t;
        OrbitCamera wide = new OrbitCamera(new Vector3f(sx, sy, 0.1f), (float) Math.toRadians(-90), (float) Math.toRadians(89), 3f);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)) {
            r.setBalls(List.of());
            r.setObstacles(List.of(tower));
            off.bind();
            r.render(wide, W, H, 0f);
            Path png = TestCourses.screenshotDir().resolve("tower-shadow.png");
            off.savePng(png);
            Pixels p = Pixels.read(png);
            r.setShadows(false);
            off.bind();
            r.render(wide, W, H, 0f);
            Path plain = TestCourses.screenshotDir().resolve("tower-no-shadow.png");
            off.savePng(plain);
            Pixels q = Pixels.read(plain);
            float[] s = wide.project(new Vector3f(sx, sy, 0.1f), W, H);
            int x = Math.round(s[0]), y = Math.round(s[1]);
            assertTrue(luminance(p, x, y) < 0.75 * luminance(q, x, y),
                    "no tower shadow 3.6 m up the ray: with " + p.describe(x, y) + ", without " + q.describe(x, y));
        }
    }

    @Test
    void theMinimapShowsObstaclesAddedAfterItWasFirstDrawn() {
        Course course = TestCourses.flat(); // bounds -5..5; the minimap pads them by 2%: 10.4 m across
        Obstacle thick = new Obstacle.Wall(new Vec2(1, -3), new Vec2(1, 3), 0.4, 0.3, 0.7);
        int size = 240, x0 = 20, y0 = 20, border = 2, inner = size - 2 * border;
        int px = x0 + border + Math.round((float) ((1 + 5.2) / 10.4 * inner));
        int py = y0 + border + Math.round((float) ((5.2 - 1.0) / 10.4 * inner));
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)) {
            Pixels[] shots = new Pixels[2];
            for (int k = 0; k < 2; k++) {
                if (k == 1) r.setObstacles(List.of(thick));
                off.bind();
                r.render(ABOVE, W, H, 0f);
                r.renderMinimap(x0, y0, size, W, H);
                assertEquals(GL_NO_ERROR, glGetError());
                Path png = TestCourses.screenshotDir().resolve("minimap-obstacle-" + k + ".png");
                off.savePng(png);
                shots[k] = Pixels.read(png);
            }
            assertTrue(grassy(shots[0], new int[]{px, py}), "no wall on the first minimap: " + shots[0].describe(px, py));
            assertTrue(wooden(shots[1], new int[]{px, py}), "the wall on the redrawn minimap: " + shots[1].describe(px, py));
        }
    }

    /**
     * The software tier draws the windmill from its lighter twin (288 triangles for 10,560), the
     * course keeps the full model for the physics, and the picture barely changes: the twin's
     * outline is the full one's within 0.2% of the tower's radius.
     */
    @Test
    void theSoftwareTierDrawsTheWindmillsTwinAndLooksTheSame() throws Exception {
        minigolf.physics.World w = minigolf.physics.World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "windmill.json"));
        Course course = w.course();
        Obstacle.Model mill = (Obstacle.Model) course.obstacles().get(0);
        // The same model under a file name with no twin beside it: drawn in full at every tier.
        Obstacle.Model untwinned = new Obstacle.Model("models/untwinned.obj", mill.position(), mill.rotationDeg(), mill.scale(),
                mill.restitution(), mill.mesh());
        java.util.List<Obstacle> others = course.obstacles().subList(1, course.obstacles().size());
        java.util.List<Obstacle> full = new java.util.ArrayList<>(java.util.List.of(untwinned));
        full.addAll(others);
        int W2 = 640, H2 = 360;
        OrbitCamera cam = OrbitCamera.behindBall(course, w.terrain(), (float) W2 / H2);
        int[][] pictures = new int[2][];
        int[] triangles = new int[2];
        for (int k = 0; k < 2; k++) {
            Course drawn = k == 0 ? course : course.withObstacles(full);
            try (Offscreen off = new Offscreen(W2, H2, 0);
                 SceneRenderer r = new SceneRenderer(drawn, w.terrain(), TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
                r.setBalls(List.of());
                off.bind();
                r.render(cam, W2, H2, 0f);
                assertEquals(GL_NO_ERROR, glGetError());
                Path png = TestCourses.screenshotDir().resolve(k == 0 ? "windmill-twin.png" : "windmill-full-software.png");
                off.savePng(png);
                pictures[k] = Pixels.read(png).rgb();
                triangles[k] = r.obstaclesPass().solidTriangles();
                assertSame(mill.mesh(), ((Obstacle.Model) r.obstaclesPass().obstacles().get(0)).mesh(), "the pass keeps the course's model");
            }
        }
        assertEquals(10560 - 288, triangles[1] - triangles[0], "the twin's 288 triangles drawn instead of 10,560");
        int millPixels = 0, differ = 0;
        for (int i = 0; i < pictures[0].length; i++) {
            int a = pictures[0][i], b = pictures[1][i];
            int d = 0;
            for (int shift = 0; shift < 24; shift += 8) d = Math.max(d, Math.abs(((a >> shift) & 0xff) - ((b >> shift) & 0xff)));
            if (d > 24) differ++;
            // Whitewash and thatch: light and warm, unlike the grass round it.
            if (((b >> 16) & 0xff) > 120 && ((b >> 16) & 0xff) >= ((b >> 8) & 0xff)) millPixels++;
        }
        assertTrue(millPixels > 2000, "the windmill is in view: " + millPixels + " pixels");
        assertTrue(differ * 50 < millPixels, differ + " of the windmill's " + millPixels + " pixels changed by more than 24 levels");
    }
}
