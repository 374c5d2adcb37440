package minigolf.render;

import minigolf.physics.World;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11.glGetError;

/**
 * FXAA (software quality, no MSAA): the filter compiles and draws without GL errors, softens the
 * pixels on edges (the course's silhouette against the sky, the flag) and leaves flat areas exactly
 * as they were (needs xvfb-run or EGL).
 */
class FxaaTest {
    static final int W = 480, H = 300;

    @Test
    void theFilterChangesEdgePixelsOnly() throws Exception {
        World w = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "lake.json"));
        OrbitCamera cam = OrbitCamera.behindBall(w.course(), w.terrain(), (float) W / H);
        Path dir = TestCourses.screenshotDir();
        java.nio.file.Files.createDirectories(dir);
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
            assertFalse(r.antiAliasing(), "off unless asked for");
            off.bind();
            r.setAntiAliasing(false);
            r.render(cam, W, H, 0f);
            off.savePng(dir.resolve("fxaa-off.png"));
            r.setAntiAliasing(true);
            off.bind(); // savePng left the window's framebuffer bound
            r.render(cam, W, H, 0f);
            assertEquals(GL_NO_ERROR, glGetError());
            off.savePng(dir.resolve("fxaa-on.png"));
        }
        Pixels plain = Pixels.read(dir.resolve("fxaa-off.png")), filtered = Pixels.read(dir.resolve("fxaa-on.png"));
        int edges = 0, edgesChanged = 0, flat = 0, flatChanged = 0;
        for (int y = 1; y < H - 1; y++) {
            for (int x = 1; x < W - 1; x++) {
                int contrast = 0;
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dx = -1; dx <= 1; dx++) contrast = Math.max(contrast, Math.abs(luma(plain, x + dx, y + dy) - luma(plain, x, y)));
                }
                boolean changed = plain.r(x, y) != filtered.r(x, y) || plain.g(x, y) != filtered.g(x, y) || plain.b(x, y) != filtered.b(x, y);
                if (contrast >= 60) {
                    edges++;
                    if (changed) edgesChanged++;
                } else if (contrast <= 2) {
                    flat++;
                    if (changed) flatChanged++;
                }
            }
        }
        assertTrue(edges > 200, "the view has edges: " + edges);
        assertTrue(edgesChanged > edges / 2, edgesChanged + " of " + edges + " edge pixels changed");
        assertTrue(flat > W * H / 4, "and flat areas: " + flat);
        assertEquals(0, flatChanged, "flat pixels changed");
    }

    private static int luma(Pixels p, int x, int y) {
        return (299 * p.r(x, y) + 587 * p.g(x, y) + 114 * p.b(x, y)) / 1000;
    }
}
