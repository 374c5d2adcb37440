package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The software tier draws the obstacles' triangles the sun cannot light without the shadow tap
 * (BacklitSplit): the split keeps every triangle once, moves only flat, closed, non-cloth ones facing
 * away from the sun, and the picture stays as it was (the last test needs an OpenGL context).
 */
class BacklitSplitTest {
    private static final int W = 480, H = 270;

    /** One vertex: position, normal, colour and material id (ObstacleMeshes' layout {3, 3, 4}). */
    private static void vertex(List<Float> v, float x, float y, float z, float nx, float ny, float nz, float material) {
        for (float f : new float[]{x, y, z, nx, ny, nz, 0.5f, 0.5f, 0.5f, material}) v.add(f);
    }

    @Test
    void theSplitKeepsEveryTriangleOnceAndMovesOnlyFlatClosedOnesTurnedFromTheSun() {
        List<Float> v = new ArrayList<>();
        vertex(v, 0, 0, 0, 1, 0, 0, 1);   // 0-2: a flat face towards +x
        vertex(v, 0, 1, 0, 1, 0, 0, 1);
        vertex(v, 0, 0, 1, 1, 0, 0, 1);
        vertex(v, 1, 0, 0, -1, 0, 0, 1);  // 3-5: a flat face towards -x
        vertex(v, 1, 1, 0, -1, 0, 0, 1);
        vertex(v, 1, 0, 1, -1, 0, 0, 1);
        vertex(v, 2, 0, 0, -1, 0, 0, 1);  // 6-8: towards -x but smooth (one normal differs)
        vertex(v, 2, 1, 0, -1, 0, 0, 1);
        vertex(v, 2, 0, 1, -0.9f, 0.1f, 0, 1);
        vertex(v, 3, 0, 0, -1, 0, 0, 6);  // 9-11: cloth towards -x
        vertex(v, 3, 1, 0, -1, 0, 0, 6);
        vertex(v, 3, 0, 1, -1, 0, 0, 6);
        float[] vertices = new float[v.size()];
        for (int i = 0; i < vertices.length; i++) vertices[i] = v.get(i);
        // Piece A: faces +x, -x; piece B (open): -x again; piece C: smooth and cloth.
        int[] indices = {0, 1, 2, 3, 4, 5, 3, 5, 4, 6, 7, 8, 9, 10, 11};
        MeshData mesh = new MeshData(new int[]{3, 3, 4}, vertices, indices);
        float[] box = {0, 0, 0, 1, 1, 1};
        List<ObstacleMeshes.Piece> pieces = List.of(new ObstacleMeshes.Piece(0, 6, box), new ObstacleMeshes.Piece(6, 3, box, true),
                new ObstacleMeshes.Piece(9, 6, box));
        BacklitSplit.Result r = BacklitSplit.split(mesh, pieces, new Vector3f(0.6f, 0, 0.8f));
        // Only A's -x face is backlit: the open piece, the smooth and the cloth triangles stay lit.
        assertArrayEquals(new int[]{0, 1, 2, 3, 5, 4, 6, 7, 8, 9, 10, 11, 3, 4, 5}, r.indices());
        assertEquals(List.of(0, 3, 6), r.lit().stream().map(ObstacleMeshes.Piece::first).toList());
        assertEquals(List.of(3, 3, 6), r.lit().stream().map(ObstacleMeshes.Piece::count).toList());
        assertEquals(List.of(false, true, false), r.lit().stream().map(ObstacleMeshes.Piece::open).toList());
        assertEquals(1, r.backlit().size());
        assertEquals(12, r.backlit().get(0).first());
        assertEquals(3, r.backlit().get(0).count());
        assertSame(box, r.backlit().get(0).box());
        // The sun overhead (n.l = 0 on both walls): A's two faces both backlit, B (open) stays.
        BacklitSplit.Result overhead = BacklitSplit.split(mesh, pieces, new Vector3f(0, 0, 1));
        assertEquals(6, overhead.backlit().stream().mapToInt(ObstacleMeshes.Piece::count).sum());
        assertThrows(IllegalArgumentException.class, () -> BacklitSplit.split(mesh, pieces.subList(0, 2), new Vector3f(0, 0, 1)));
    }

    @Test
    void drawingTheBacklitPartsWithoutTheTapLeavesThePictureAsItWas() throws Exception {
        for (String hole : new String[]{"seaside/07-jetty.json", "seaside/18-lighthouse-point.json"}) {
            World w = TestCourses.worldHole(hole);
            Vector3f centre = TestCourses.middle(w.course());
            try (Offscreen off = new Offscreen(W, H, 0);
                 SceneRenderer r = new SceneRenderer(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
                r.setBalls(List.of());
                int backlit = 0;
                for (int heading = 0; heading < 360; heading += 90) {
                    OrbitCamera cam = new OrbitCamera(centre, (float) Math.toRadians(heading), (float) Math.toRadians(20), 7f);
                    int[] split = draw(off, r, cam, true, "backlit-split.png");
                    backlit = r.obstaclesPass().backlitTriangles();
                    int[] whole = draw(off, r, cam, false, "backlit-whole.png");
                    assertEquals(0, r.obstaclesPass().backlitTriangles(), "unsplit");
                    int differ = 0;
                    for (int i = 0; i < split.length; i++) if (split[i] != whole[i]) differ++;
                    assertEquals(0, differ, hole + " heading " + heading + ": pixels that differ");
                }
                assertTrue(backlit > 0, hole + ": some triangles backlit");
            }
        }
    }

    private static int[] draw(Offscreen off, SceneRenderer r, OrbitCamera cam, boolean split, String name) {
        r.obstaclesPass().splitBacklit(split);
        off.bind();
        r.render(cam, W, H, 0f);
        Path png = TestCourses.screenshotDir().resolve(name);
        off.savePng(png);
        return Pixels.read(png).rgb();
    }
}
