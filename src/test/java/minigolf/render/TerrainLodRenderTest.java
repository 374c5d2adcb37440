package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.terrain.Terrains;
import minigolf.terrain.Terrain;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A 40 m x 40 m hilly course seen from near the ground: the chunks are drawn at several levels,
 * and no sky shows through the terrain where the full-resolution mesh has none (no cracks at the
 * chunks' seams), while most of the triangles are saved (needs xvfb-run or EGL). Watertight seams
 * are proved on the CPU (TerrainLodTest): with coarse chunk borders (T-junctions) llvmpipe showed
 * no gap here, so this test alone would not catch them.
 */
class TerrainLodRenderTest {
    static final int W = 640, H = 400;

    @Test
    void chunksAtSeveralLevelsLeaveNoCracks() throws Exception {
        Course course = new Course(Course.FORMAT, "Hills 40 m",
                new TerrainSpec.HeightExpression("0.6 + 0.35*sin(0.9*x)*cos(0.7*y)"),
                new Bounds(-20, -20, 20, 20), TestCourses.PHYSICS, new Vec2(-15, 0),
                new Hole(new Vec2(15, 2), 0.1, HoleRule.REST, null), List.of());
        Terrain terrain = Terrains.create(course.terrain());
        OrbitCamera cam = new OrbitCamera(new Vector3f(-4, 0, 0.6f), (float) Math.toRadians(200), (float) Math.toRadians(24), 22);
        Path dir = TestCourses.screenshotDir();
        java.nio.file.Files.createDirectories(dir);
        int[] lodHistogram;
        int lodIndices, fullIndices;
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, terrain, TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
            off.bind();
            r.render(cam, W, H, 0f);
            off.savePng(dir.resolve("lod-on.png"));
            lodHistogram = r.terrainPass().lastLevelHistogram();
            lodIndices = r.terrainPass().lastLodIndexCount();
            r.terrainPass().setLevelOfDetail(false);
            r.render(cam, W, H, 0f);
            off.savePng(dir.resolve("lod-off.png"));
            fullIndices = r.terrainPass().lastLodIndexCount();
        }
        long levelsUsed = Arrays.stream(lodHistogram).filter(n -> n > 0).count();
        assertTrue(levelsUsed >= 2, "levels in use: " + Arrays.toString(lodHistogram));
        assertTrue(lodIndices < fullIndices / 2, lodIndices + " of " + fullIndices + " indices");
        Pixels on = Pixels.read(dir.resolve("lod-on.png")), offImage = Pixels.read(dir.resolve("lod-off.png"));
        int sky = 0, cracks = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                boolean skyOff = isSky(offImage, x, y), skyOn = isSky(on, x, y);
                if (skyOff) sky++;
                if (skyOn && !skyOff) cracks++;
            }
        }
        assertTrue(sky > W * H / 20, "the view shows sky above the far edge: " + sky);
        assertTrue(sky < W * H / 2, "and mostly terrain: " + sky);
        assertEquals(0, cracks, "sky pixels where the full mesh has terrain");
    }

    private static boolean isSky(Pixels p, int x, int y) {
        return p.b(x, y) > p.g(x, y) + 10 && p.b(x, y) > p.r(x, y) + 20;
    }
}
