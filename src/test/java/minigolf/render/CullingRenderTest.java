package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11.glGetError;

import java.nio.file.Path;
import java.util.List;
import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The software tier skips the faces turned away from the camera (RenderQuality.cullBackFaces): the
 * terrain, the obstacles (the windmill's twin with its eaves closed) and the props are closed and
 * wound alike, so the picture stays as it was drawn with every face, seen from all four sides and
 * from low down, the flag's cloth (never culled) included. Needs an OpenGL context.
 */
class CullingRenderTest {
    private static final int W = 480, H = 270;

    @Test
    void cullingTheFarFacesLeavesThePictureAsItWas() throws Exception {
        assertTrue(RenderQuality.SOFTWARE.cullBackFaces() && !RenderQuality.HIGH.cullBackFaces(), "the software tier only");
        for (String hole : new String[]{"seaside/18-lighthouse-point.json", "winter/18-the-keep.json"}) {
            World w = TestCourses.worldHole(hole);
            Vector3f centre = TestCourses.middle(w.course());
            try (Offscreen off = new Offscreen(W, H, 0);
                 SceneRenderer r = new SceneRenderer(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN, RenderQuality.SOFTWARE)) {
                r.setBalls(List.of());
                for (int heading = 0; heading < 360; heading += 90) {
                    for (int pitch : new int[]{8, 35}) {
                        OrbitCamera cam = new OrbitCamera(centre, (float) Math.toRadians(heading), (float) Math.toRadians(pitch), 9f);
                        String view = hole + " heading " + heading + " pitch " + pitch;
                        int[] culled = draw(off, r, cam, true, "culled.png"), all = draw(off, r, cam, false, "all-faces.png");
                        int differ = 0;
                        for (int i = 0; i < culled.length; i++) {
                            int d = 0;
                            for (int shift = 0; shift < 24; shift += 8) {
                                d = Math.max(d, Math.abs(((culled[i] >> shift) & 0xff) - ((all[i] >> shift) & 0xff)));
                            }
                            if (d > 24) differ++;
                        }
                        // Silhouette pixels where a far face peeked past a near one (a rock's dark rim) may go.
                        assertTrue(differ * 500 < culled.length, view + ": " + differ + " pixels changed by more than 24 levels");
                    }
                }
            }
        }
    }

    /** A model that is not closed (here one square) keeps every face at the software tier too; a closed one (the windmill's twin) does not. */
    @Test
    void modelsThatAreNotClosedKeepTheirFarFaces() {
        minigolf.mesh.TriangleMesh square = new minigolf.mesh.TriangleMesh(new float[]{0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1},
                new float[12], new float[8], new int[]{0, 1, 2, 0, 2, 3}, List.of(), List.of());
        minigolf.mesh.TriangleMesh twin = minigolf.course.ModelTwins.low("models/windmill.obj", null);
        List<minigolf.course.Obstacle> models = List.of(
                new minigolf.course.Obstacle.Model("models/square.obj", new minigolf.course.Vec3(0, 0, 0), 0, 1, 0.5, square),
                new minigolf.course.Obstacle.Model("models/windmill.obj", new minigolf.course.Vec3(2, 0, 0), 0, 1, 0.5, twin));
        var pieces = ObstacleMeshes.build(models, (x, y) -> 0, m -> MaterialLibrary.empty()).solidPieces();
        assertEquals(List.of(true, false), pieces.stream().map(ObstacleMeshes.Piece::open).toList());
    }

    private static int[] draw(Offscreen off, SceneRenderer r, OrbitCamera cam, boolean cull, String name) {
        r.cullBackFaces(cull);
        off.bind();
        r.render(cam, W, H, 0f);
        assertEquals(GL_NO_ERROR, glGetError(), name);
        Path png = TestCourses.screenshotDir().resolve(name);
        off.savePng(png);
        return Pixels.read(png).rgb();
    }
}
