package minigolf.render;

import minigolf.physics.World;
import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Terrain cells drawn without the shadow tap: the search over a synthetic map (no GL), and the
 * pictures with and without it (needs xvfb-run): they must not differ.
 */
class SunlitCellsTest {
    /** A flat 4 x 4 m grid at z = 0, 0.5 m cells (9 x 9 vertices), seen by a light straight above (orthographic). */
    static final int COLS = 9, ROWS = 9, SIZE = 64;
    static final Matrix4f TOP_LIGHT = new Matrix4f().setOrtho(-2, 2, -2, 2, -5, 5);

    static float[] grid() {
        float[] v = new float[COLS * ROWS * 9];
        for (int j = 0; j < ROWS; j++) {
            for (int i = 0; i < COLS; i++) {
                int k = (j * COLS + i) * 9;
                v[k] = -2 + 0.5f * i;
                v[k + 1] = -2 + 0.5f * j;
            }
        }
        return v;
    }

    /** The depth map of the plane z = 0 seen from above (depth 0.5), with a caster's texels nearer the light. */
    static float[] map(int x0, int y0, int x1, int y1) {
        float[] d = new float[SIZE * SIZE];
        java.util.Arrays.fill(d, 0.5f);
        for (int y = y0; y < y1; y++) for (int x = x0; x < x1; x++) d[y * SIZE + x] = 0.45f;
        return d;
    }

    @Test
    void anOpenPlaneIsSunlitEverywhere() {
        boolean[] s = SunlitCells.shadowed(map(0, 0, 0, 0), SIZE, TOP_LIGHT, 1e-4f, grid(), 9, COLS, ROWS);
        assertEquals(64, s.length);
        for (boolean b : s) assertFalse(b);
    }

    @Test
    void aCastersTexelsMarkTheCellsUnderItAndTheirNeighbours() {
        // Texels 30..33 (of 64 over 4 m: 6.25 cm each) in x and y: about (-0.125 .. 0.125, same) in metres,
        // under the four cells round the centre; widened by one cell all round: the 4 x 4 block 2..5.
        boolean[] s = SunlitCells.shadowed(map(30, 30, 34, 34), SIZE, TOP_LIGHT, 1e-4f, grid(), 9, COLS, ROWS);
        for (int j = 0; j < 8; j++) {
            for (int i = 0; i < 8; i++) {
                boolean expected = i >= 2 && i <= 5 && j >= 2 && j <= 5;
                assertEquals(expected, s[j * 8 + i], "cell " + i + ", " + j);
            }
        }
    }

    @Test
    void aSlopeRisingTowardsTheLightIsNotItsOwnShadow() {
        // The plane z = 0.3 x seen from above: depths fall steadily across it; no caster.
        float[] v = grid();
        float[] d = new float[SIZE * SIZE];
        for (int k = 0; k < COLS * ROWS; k++) v[k * 9 + 2] = 0.3f * v[k * 9];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                float wx = -2 + 4f * (x + 0.5f) / SIZE;
                d[y * SIZE + x] = 0.5f - 0.3f * wx / 10f; // the ortho's depth: -z over 10 m, to [0, 1]
            }
        }
        boolean[] s = SunlitCells.shadowed(d, SIZE, TOP_LIGHT, 1e-4f, v, 9, COLS, ROWS);
        for (boolean b : s) assertFalse(b);
    }

    @Test
    void runsAlternateAndFoldShortSunlitGaps() {
        boolean T = true, F = false;
        // shadowed 0-1, sunlit 2-3 (short: folded), shadowed 4, sunlit 5-14 (long), shadowed 15.
        boolean[] mask = {T, T, F, F, T, F, F, F, F, F, F, F, F, F, F, T};
        assertArrayEquals(new int[]{0, 5, 15, 16}, SunlitCells.runs(mask, 3));
        // Without folding, every change is a run boundary; a leading sunlit run gives an empty shadowed one.
        assertArrayEquals(new int[]{0, 2, 4, 5, 15, 16}, SunlitCells.runs(mask, 0));
        assertArrayEquals(new int[]{0, 0, 3}, SunlitCells.runs(new boolean[]{F, F, F}, 8));
    }

    /** The split must not change a pixel: the same frame with every cell tapped. */
    @Test
    void theSunlitSplitChangesNoPixel() {
        RenderQuality split = RenderQuality.SOFTWARE;
        RenderQuality tapped = new RenderQuality("software-tapped", split.samples(), split.shadowMapSize(),
                split.waterTargetScale(), split.shadowsInWater(), split.shadowTaps(), split.vertexLit(),
                split.terrainSpacing(), false, split.ballShadowRedraw(), split.waterImages(), split.cullBackFaces());
        for (String name : List.of("walled.json", "windmill.json", "lake.json")) {
            World w;
            try {
                w = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", name));
            } catch (Exception e) {
                throw new AssertionError(e);
            }
            Pixels a = draw(w, split, "sunlit-split-" + name + ".png");
            Pixels b = draw(w, tapped, "sunlit-tapped-" + name + ".png");
            int differ = 0;
            String first = null;
            for (int y = 0; y < a.height(); y++) {
                for (int x = 0; x < a.width(); x++) {
                    int d = Math.max(Math.abs(a.r(x, y) - b.r(x, y)), Math.max(Math.abs(a.g(x, y) - b.g(x, y)), Math.abs(a.b(x, y) - b.b(x, y))));
                    if (d > 2) {
                        differ++;
                        if (first == null) first = a.describe(x, y) + " vs " + b.describe(x, y);
                    }
                }
            }
            assertEquals(0, differ, name + ": pixels that differ, first " + first);
        }
    }

    static Pixels draw(World w, RenderQuality q, String file) {
        Path png = TestCourses.screenshotDir().resolve(file);
        int width = 800, height = 450;
        try (Offscreen off = new Offscreen(width, height, 0);
             SceneRenderer r = new SceneRenderer(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN, q)) {
            OrbitCamera cam = OrbitCamera.behindBall(w.course(), w.terrain(), (float) width / height);
            off.bind();
            r.render(cam, width, height, 0f);
            if (q.sunlitTerrain()) {
                assertTrue(r.terrainPass().sunlitIndexCount() > 0, "no sunlit cell found");
                // A near chunk (full resolution) drawn part with the tap, part without (TerrainPass.sortLevel0).
                assertTrue(r.terrainPass().lod().chunks().stream().anyMatch(c -> c.shadowedAtLevel0 > 0 && c.shadowedAtLevel0 < c.count[0]),
                        file + ": no chunk split between shadowed and sunlit cells");
            }
            off.savePng(png);
        }
        return Pixels.read(png);
    }
}
