package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * Each world renders as its own place (needs an OpenGL context): the ground round the course is grass,
 * sand or snow, the seaside has the sea below its horizon, and the flag's cloth moves with time.
 */
class WorldRenderTest {
    static final int W = 480, H = 270;
    static final Obstacle.Wall RAIL = new Obstacle.Wall(new Vec2(-4, -1), new Vec2(4, -1), 0.08, 0.1, 0.75);

    static Pixels shot(String world, OrbitCamera cam, RenderQuality q, float time, String name) {
        Course course = TestCourses.flat().withObstacles(List.of(RAIL)).withWorld(world);
        Path png = TestCourses.screenshotDir().resolve(name);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, q)) {
            r.setBalls(List.of());
            off.bind();
            r.render(cam, W, H, time);
            assertEquals(0, org.lwjgl.opengl.GL11.glGetError(), world);
            off.savePng(png);
        }
        return Pixels.read(png);
    }

    /** From high above the course: the shore (14 m off) and the sea beyond it fill the picture's edges. */
    static OrbitCamera above() {
        return new OrbitCamera(new Vector3f(0, 0, 0.1f), (float) Math.toRadians(-90), (float) Math.toRadians(35), 30f);
    }

    /** The flat test course with a rail by the sea, at the software tier, no balls. */
    private static SceneRenderer seasideSoftware() {
        Course course = TestCourses.flat().withObstacles(List.of(RAIL)).withWorld("seaside");
        SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE);
        r.setBalls(List.of());
        return r;
    }

    /** The largest difference of one colour channel between two pixels (0xRRGGBB). */
    private static int levels(int a, int b) {
        int d = 0;
        for (int shift = 0; shift < 24; shift += 8) d = Math.max(d, Math.abs(((a >> shift) & 0xff) - ((b >> shift) & 0xff)));
        return d;
    }

    /** A low view along the course's long side: ground on both sides of it, the horizon near the top. */
    static OrbitCamera low() {
        return new OrbitCamera(new Vector3f(0, 0, 0.1f), (float) Math.toRadians(-90), (float) Math.toRadians(10), 14f);
    }

    @Test
    void theGroundRoundTheCourseIsEachWorldsOwn() {
        for (RenderQuality q : new RenderQuality[]{RenderQuality.HIGH, RenderQuality.SOFTWARE}) {
            // The bottom corners show the ground a few metres beside the course.
            int[] meadow = mean(shot("meadowbrook", low(), q, 0, "world-meadowbrook-" + q.name() + ".png"));
            int[] canyon = mean(shot("canyon", low(), q, 0, "world-canyon-" + q.name() + ".png"));
            int[] winter = mean(shot("winter", low(), q, 0, "world-winter-" + q.name() + ".png"));
            assertTrue(meadow[1] > meadow[0] + 10 && meadow[1] > meadow[2] + 10, q.name() + " grass " + java.util.Arrays.toString(meadow));
            assertTrue(canyon[0] > canyon[1] + 20 && canyon[1] > canyon[2] + 10, q.name() + " sand " + java.util.Arrays.toString(canyon));
            assertTrue(winter[0] > 170 && winter[1] > 170 && winter[2] > 190, q.name() + " snow " + java.util.Arrays.toString(winter));
        }
    }

    /** The mean colour of the image's bottom-left and bottom-right 40 x 30 pixels. */
    private static int[] mean(Pixels p) {
        long r = 0, g = 0, b = 0, n = 0;
        for (int y = H - 30; y < H; y++) {
            for (int x : new int[]{0, W - 40}) {
                for (int dx = 0; dx < 40; dx++) {
                    r += p.r(x + dx, y);
                    g += p.g(x + dx, y);
                    b += p.b(x + dx, y);
                    n++;
                }
            }
        }
        return new int[]{(int) (r / n), (int) (g / n), (int) (b / n)};
    }

    @Test
    void theSeasideHasTheSeaBelowItsHorizon() {
        // From high above the course the shore (14 m off) and the sea beyond it fill the picture's edges:
        // deep blue-green water in the seaside world only (Meadowbrook's far meadow fades to a light haze).
        OrbitCamera out = above();
        Pixels sea = shot("seaside", out, RenderQuality.SOFTWARE, 0, "world-seaside-sea.png");
        Pixels meadow = shot("meadowbrook", out, RenderQuality.SOFTWARE, 0, "world-meadowbrook-far.png");
        int seaPixels = 0, meadowPixels = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (deepWater(sea, x, y)) seaPixels++;
                if (deepWater(meadow, x, y)) meadowPixels++;
            }
        }
        assertTrue(seaPixels > W * H / 10, "sea pixels " + seaPixels);
        assertEquals(0, meadowPixels, "Meadowbrook has no sea");
    }

    private static boolean deepWater(Pixels p, int x, int y) {
        return p.b(x, y) > p.r(x, y) + 40 && p.g(x, y) > p.r(x, y) + 20 && p.r(x, y) < 90 && p.b(x, y) < 190;
    }

    @Test
    void theFlagWaves() {
        // From beside the hole (the flat course's hole is at 3.3, 3.0), the cloth is drawn at two moments.
        OrbitCamera cam = new OrbitCamera(new Vector3f(3.3f, 3.0f, 0.8f), (float) Math.toRadians(-60), (float) Math.toRadians(12), 2.2f);
        Pixels a = shot("meadowbrook", cam, RenderQuality.HIGH, 0, "flag-t0.png");
        Pixels b = shot("meadowbrook", cam, RenderQuality.HIGH, 0.4f, "flag-t04.png");
        int changed = 0, red = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                boolean ra = a.r(x, y) > 120 && a.r(x, y) > 2 * a.g(x, y), rb = b.r(x, y) > 120 && b.r(x, y) > 2 * b.g(x, y);
                if (ra) red++;
                if (ra != rb) changed++;
            }
        }
        assertTrue(red > 200, "the cloth is in view: " + red + " red pixels");
        assertTrue(changed > red / 10, "the cloth moved: " + changed + " of " + red + " pixels changed");
    }

    /**
     * The software tier's sky by the sea sorts its cells by a shore built once with the ground (not
     * per frame), and drawing the cells off the shore's band from their grid corners leaves the
     * picture as the per-pixel sea everywhere drew it.
     */
    @Test
    void theShoreIsBuiltWithTheGroundAndTheSplitLeavesThePictureAsItWas() {
        OrbitCamera out = above();
        try (Offscreen off = new Offscreen(W, H, 0); SceneRenderer r = seasideSoftware()) {
            SkyPass sky = r.skyPass();
            assertNotNull(sky.shore(), "the seaside's software sky has a shore");
            for (OrbitCamera cam : new OrbitCamera[]{out, low()}) {
                SkyPass.Shore shore = sky.shore();
                Pixels split = draw(off, r, cam, "sea-split.png");
                int[] counts = sky.lastCounts();
                assertTrue(counts[4] + counts[6] > 0, "some ground cells skip the per-pixel shore");
                assertSame(shore, sky.shore(), "the same shore frame after frame");
                sky.splitShore(false);
                Pixels whole = draw(off, r, cam, "sea-whole.png");
                counts = sky.lastCounts();
                assertEquals(0, counts[4] + counts[5] + counts[6] + counts[7], "every cell per pixel");
                sky.splitShore(true);
                int worst = 0;
                for (int i = 0; i < split.rgb().length; i++) worst = Math.max(worst, levels(split.rgb()[i], whole.rgb()[i]));
                assertTrue(worst <= 3, "the pictures differ by up to " + worst + " levels");
            }
            SkyPass.Shore first = sky.shore();
            sky.setGround(first.level() - 1, new float[]{0.3f, 0.5f, 0.2f}, SurroundingsPass.FADE_START, SurroundingsPass.FADE_END);
            assertEquals(first.level() - 1, sky.shore().level(), 1e-6, "a new ground, a new shore");
            assertArrayEquals(first.courseRect(), sky.shore().courseRect());
        }
    }

    /**
     * The software tier's shore (SIMPLE_SHORE: the foam's exp and sin by polynomials, its fade per vertex)
     * draws the picture the high tier's arithmetic draws, within the approximations' bound: the foam's
     * weight is off by at most 0.035 (the bell) + 0.033 (the swing's 0.056 moves the line by 0.04 of its
     * width), times its 0.6 strength and the foam-to-water contrast: under 12 levels; everywhere else the same.
     */
    @Test
    void theSimpleShoreDrawsTheShoreAsTheFullArithmetic() {
        OrbitCamera out = above();
        try (Offscreen off = new Offscreen(W, H, 0); SceneRenderer r = seasideSoftware()) {
            SkyPass sky = r.skyPass();
            for (float time : new float[]{0f, 2.5f}) {
                Pixels simple = draw(off, r, out, time, "shore-simple.png");
                int[] counts = sky.lastCounts();
                assertTrue(counts[0] + counts[2] > 0, "some cells draw the shore per pixel");
                sky.simpleShore(false);
                Pixels full = draw(off, r, out, time, "shore-full.png");
                sky.simpleShore(true);
                int worst = 0, differing = 0, foam = 0;
                for (int i = 0; i < simple.rgb().length; i++) {
                    int d = levels(simple.rgb()[i], full.rgb()[i]);
                    worst = Math.max(worst, d);
                    if (d > 2) differing++;
                    if (isFoam(full.rgb()[i])) foam++;
                }
                assertTrue(foam > 100, "the full shore shows its foam: " + foam + " pixels");
                assertTrue(worst <= 12, "at " + time + " s the pictures differ by up to " + worst + " levels");
                assertTrue(differing < foam * 3, "at " + time + " s " + differing + " pixels differ by more than 2 levels ("
                        + foam + " foam pixels)");
            }
        }
    }

    /** Near-white with a cool tint: the foam's colour (0.95, 0.97, 0.98) over sand or water. */
    private static boolean isFoam(int rgb) {
        int r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
        return r > 200 && g > 205 && b > 205 && b >= r;
    }

    private static Pixels draw(Offscreen off, SceneRenderer r, OrbitCamera cam, String name) {
        return draw(off, r, cam, 0f, name);
    }

    private static Pixels draw(Offscreen off, SceneRenderer r, OrbitCamera cam, float time, String name) {
        off.bind();
        r.render(cam, W, H, time);
        assertEquals(0, org.lwjgl.opengl.GL11.glGetError(), name);
        Path png = TestCourses.screenshotDir().resolve(name);
        off.savePng(png);
        return Pixels.read(png);
    }
}
