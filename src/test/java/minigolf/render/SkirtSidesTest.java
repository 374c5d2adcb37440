package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The skirts' sides (TerrainMesh.skirtSides) are the skirts' index ranges with one outward normal each,
 * and the software tier's terrain draws the sides turned from the sun without the shadow tap: the
 * same pixels (needs an OpenGL context for the last test).
 */
class SkirtSidesTest {
    static final int W = 480, H = 270;

    @Test
    void theSidesCoverTheSkirtsAndEachHasOneNormal() {
        TerrainMesh mesh = TerrainMesh.build(TestCourses.flat(), TestCourses.FLAT, TerrainMesh.ColorMode.GREEN);
        int[] idx = mesh.data().indices();
        float[] v = mesh.data().vertices();
        List<TerrainMesh.SkirtSide> sides = mesh.skirtSides();
        assertEquals(4, sides.size());
        int next = mesh.cellStarts()[mesh.cellStarts().length - 1];
        int[][] normals = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        for (int k = 0; k < 4; k++) {
            TerrainMesh.SkirtSide side = sides.get(k);
            assertEquals(next, side.first(), "side " + k + " follows the one before");
            assertEquals(0, side.count() % 3);
            assertArrayEquals(normals[k], new int[]{side.normalX(), side.normalY()}, "side " + k);
            for (int i = side.first(); i < side.first() + side.count(); i++) {
                int at = idx[i] * TerrainMesh.STRIDE;
                assertEquals(side.normalX(), v[at + 3], 0f, "side " + k + " index " + i);
                assertEquals(side.normalY(), v[at + 4], 0f, "side " + k + " index " + i);
                assertEquals(0f, v[at + 5], 0f, "side " + k + " index " + i);
            }
            next += side.count();
        }
        assertEquals(idx.length, next, "the four sides end where the indices end");
    }

    @Test
    void aSideIsBacklitWhereTheSunMeetsItAtNinetyDegreesOrMore() {
        Vector3f sun = new Vector3f(0.8f, -0.3f, 0.5f);
        List<TerrainMesh.SkirtSide> sides = TerrainMesh.build(TestCourses.flat(), TestCourses.FLAT, TerrainMesh.ColorMode.GREEN)
                .skirtSides();
        // y = min faces -y (n.l = 0.3: lit), x = max faces +x (0.8: lit), y = max (-0.3) and x = min (-0.8) not.
        assertFalse(TerrainPass.backlit(sides.get(0), sun));
        assertFalse(TerrainPass.backlit(sides.get(1), sun));
        assertTrue(TerrainPass.backlit(sides.get(2), sun));
        assertTrue(TerrainPass.backlit(sides.get(3), sun));
        // Grazing light (n.l = 0) gives no diffuse and no specular either.
        assertTrue(TerrainPass.backlit(sides.get(0), new Vector3f(1, 0, 1)));
    }

    @Test
    void drawingTheBacklitSidesWithoutTheTapLeavesThePictureAsItWas() {
        Course course = TestCourses.flat().withWorld("seaside");
        Path dir = TestCourses.screenshotDir();
        int backlitDrawn = 0;
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(course, TestCourses.FLAT, TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
            r.setBalls(List.of());
            for (int k = 0; k < 4; k++) {
                // Low views from the four sides, each showing the skirt below the course's near edge.
                OrbitCamera cam = new OrbitCamera(new Vector3f(0, 0, 0.1f), (float) Math.toRadians(90 * k), (float) Math.toRadians(12), 9f);
                off.bind();
                r.terrainPass().splitSkirts(true);
                r.render(cam, W, H, 0f);
                off.savePng(dir.resolve("skirts-split.png"));
                backlitDrawn += r.terrainPass().lastBacklitSkirtSides();
                r.terrainPass().splitSkirts(false);
                r.render(cam, W, H, 0f);
                assertEquals(0, r.terrainPass().lastBacklitSkirtSides());
                off.savePng(dir.resolve("skirts-whole.png"));
                Pixels split = Pixels.read(dir.resolve("skirts-split.png")), whole = Pixels.read(dir.resolve("skirts-whole.png"));
                int differing = 0;
                for (int i = 0; i < split.rgb().length; i++) if (split.rgb()[i] != whole.rgb()[i]) differing++;
                assertEquals(0, differing, "view " + k + ": pixels that differ");
            }
        }
        assertTrue(backlitDrawn > 0, "some side was drawn without the tap");
    }
}
