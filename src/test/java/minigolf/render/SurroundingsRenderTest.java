package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The meadow round the course: below the horizon and beside the course, grass, not sky (needs xvfb-run). */
class SurroundingsRenderTest {
    static final int W = 800, H = 450;

    @Test
    void groundBesideTheCourseIsMeadowInBothQualities() {
        for (RenderQuality q : new RenderQuality[]{RenderQuality.HIGH, RenderQuality.SOFTWARE}) {
            Course course = TestCourses.flat();
            // A low view along the course, so the image shows ground on both sides of it and the horizon.
            OrbitCamera cam = new OrbitCamera(new Vector3f(0, 0, 0.1f), (float) Math.toRadians(-90), (float) Math.toRadians(14), 16f);
            Path png = TestCourses.screenshotDir().resolve("surroundings-" + q.name() + ".png");
            try (Offscreen off = new Offscreen(W, H, 0);
                 SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, q)) {
                r.setBalls(List.of());
                off.bind();
                r.render(cam, W, H, 0f);
                off.savePng(png);
            }
            Pixels p = Pixels.read(png);
            FrameContext frame = new FrameContext(FrameContext.Sun.afternoon()).update(cam, W, H, 0f);
            Bounds b = course.bounds();
            double level = TerrainMesh.skirtBase(0.1, b);
            ScreenBounds slab = new ScreenBounds(frame.viewProjection, W, H);
            slab.addBox(new float[]{(float) b.minX(), (float) b.minY(), (float) level, (float) b.maxX(), (float) b.maxY(), 0.2f});
            int[] footprint = slab.rect(4, 4);
            int meadow = 0, total = 0;
            Vector4f near = new Vector4f(), far = new Vector4f();
            for (int y = 0; y < H; y += 3) {
                for (int x = 0; x < W; x += 3) {
                    int glY = H - 1 - y;
                    if (x >= footprint[0] && x < footprint[0] + footprint[2] && glY >= footprint[1] && glY < footprint[1] + footprint[3]) continue;
                    // The pixel's ray: below the horizon, meeting the meadow within 30 m (before the haze takes it).
                    float nx = (x + 0.5f) / W * 2 - 1, ny = (glY + 0.5f) / H * 2 - 1;
                    frame.inverseViewProjection.transformProject(near.set(nx, ny, -1, 1));
                    frame.inverseViewProjection.transformProject(far.set(nx, ny, 1, 1));
                    float dx = far.x - near.x, dy = far.y - near.y, dz = far.z - near.z;
                    if (dz >= 0) continue;
                    double t = (level - frame.eye.z) / dz;
                    if (Math.hypot(t * dx, t * dy) > 30) continue;
                    total++;
                    if (p.g(x, y) > p.r(x, y) + 10 && p.g(x, y) > p.b(x, y) + 10) meadow++;
                }
            }
            assertTrue(total > 2000, q.name() + ": only " + total + " pixels of near ground beside the course");
            // Trunks stand on the meadow too (brown): most, not all, are grass.
            assertTrue(meadow > 0.85 * total, q.name() + ": only " + meadow + " of " + total + " meadow pixels; bottom left " + p.describe(0, H - 1));
        }
    }
}
