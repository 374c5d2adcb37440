package minigolf.course;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import minigolf.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The software tier's lighter twins of model files (plain Java, no GL). */
class ModelTwinsTest {
    @Test
    void theTwinsNameSitsBesideTheModel() {
        assertEquals("models/windmill.low.obj", ModelTwins.lowName("models/windmill.obj"));
        assertEquals("Mill.low.OBJ", ModelTwins.lowName("Mill.OBJ"));
        assertNull(ModelTwins.lowName("models/windmill.stl"));
        assertNull(ModelTwins.lowName(".obj"));
        assertNull(ModelTwins.lowName(null));
    }

    /**
     * The bundled windmill's twin has the same shape with under 4% of the triangles (closed): every one of its
     * corners is a corner of the full model (32 of the 96 segments, the end rings of the straight
     * bands), its box is the full model's, and it names the same materials.
     */
    @Test
    void theWindmillsTwinIsTheSameShapeWithFewerTriangles() throws Exception {
        for (String file : new String[]{"models/windmill.obj", "models/windmill-tower.obj"}) {
            TriangleMesh full = ModelFiles.in(null).load(file);
            TriangleMesh low = ModelTwins.low(file, null);
            assertNotNull(low, file);
            assertTrue(low.triangleCount() * 25 < full.triangleCount(), file + ": " + low + " against " + full);
            Set<String> corners = new HashSet<>();
            for (int v = 0; v < full.vertexCount(); v++) corners.add(key(full.positions(), v));
            for (int v = 0; v < low.vertexCount(); v++) {
                assertTrue(corners.contains(key(low.positions(), v)), file + ": twin corner " + key(low.positions(), v) + " is not on the model");
            }
            assertArrayEquals(box(full), box(low), 1e-6f, file);
            assertEquals(materials(full), materials(low), file);
            assertEquals(full.materialLibraries(), low.materialLibraries(), file);
        }
        assertEquals(10560, ModelFiles.in(null).load("models/windmill.obj").triangleCount());
        // The software tier culls the faces turned away (docs/course-format.md): the twins and the sails are closed;
        // the full models stand open on the ground (drawn with every face wherever they are drawn).
        for (String file : new String[]{"models/windmill.obj", "models/windmill-tower.obj"}) {
            assertTrue(minigolf.mesh.MeshClosure.closed(ModelTwins.low(file, null)), file);
            assertFalse(minigolf.mesh.MeshClosure.closed(ModelFiles.in(null).load(file)), file);
        }
        assertTrue(minigolf.mesh.MeshClosure.closed(ModelFiles.in(null).load("models/windmill-sails.obj")));
        assertEquals(288, ModelTwins.low("models/windmill.obj", null).triangleCount()); // 164, and 124 closing it (eaves, foot, tip)
    }

    @Test
    void aModelWithoutATwinOrOutsideTheFolderHasNone(@TempDir Path dir) throws Exception {
        assertNull(ModelTwins.low("models/windmill-sails.obj", null), "the turning sails have no twin (96 triangles)");
        assertNull(ModelTwins.low("../models/windmill.obj", dir), "refused, not thrown");
        assertNull(ModelTwins.low("models/windmill.stl", dir));
        // A course's own model and twin, found in its folder before the bundled ones.
        Files.createDirectories(dir.resolve("models"));
        Files.writeString(dir.resolve("models/windmill.low.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertEquals(1, ModelTwins.low("models/windmill.obj", dir).triangleCount());
        Files.writeString(dir.resolve("models/windmill.low.obj"), "v 0 0 0\nf 1 2 9\n");
        assertNull(ModelTwins.low("models/windmill.obj", dir), "a broken twin is no twin (the model itself is drawn)");
    }

    /**
     * The cache hands the renderer the course's obstacles with each model's mesh swapped for its twin
     * (place, rotation, scale, restitution and file kept), leaves the rest as they are, and reads each
     * model file once however often the list is rebuilt (the editor rebuilds it on every change).
     */
    @Test
    void theCacheSwapsInTheTwinsAndReadsEachFileOnce() throws Exception {
        TriangleMesh mill = ModelFiles.in(null).load("models/windmill.obj");
        TriangleMesh sails = ModelFiles.in(null).load("models/windmill-sails.obj");
        Obstacle.Model model = new Obstacle.Model("models/windmill.obj", new Vec3(1, 2, 0.5), 90, 0.8, 0.6, mill);
        Obstacle.Model noTwin = new Obstacle.Model("models/windmill-sails.obj", new Vec3(1, 2, 1.5), 270, 1, 0.5, sails);
        Obstacle wall = new Obstacle.Wall(new Vec2(0, 0), new Vec2(1, 0), 0.1, 0.2, 0.8);
        ModelTwins.Cache cache = new ModelTwins.Cache(null);
        List<Obstacle> drawn = cache.drawn(List.of(wall, model, noTwin, model));
        assertEquals(4, drawn.size());
        assertSame(wall, drawn.get(0));
        assertSame(noTwin, drawn.get(2), "no twin: the model itself");
        Obstacle.Model low = (Obstacle.Model) drawn.get(1);
        assertEquals(288, low.mesh().triangleCount());
        assertEquals(List.of(model.file(), model.position(), model.rotationDeg(), model.scale(), model.restitution()),
                List.of(low.file(), low.position(), low.rotationDeg(), low.scale(), low.restitution()));
        assertEquals(2, cache.filesLookedFor(), "each file once: the mill and the sails");
        List<Obstacle> again = cache.drawn(List.of(model));
        assertSame(low.mesh(), ((Obstacle.Model) again.get(0)).mesh(), "the same twin, not read again");
        assertEquals(2, cache.filesLookedFor());
        assertEquals(10560, model.mesh().triangleCount(), "the course's own obstacle keeps the full model");
    }

    private static String key(float[] p, int v) {
        // In units of 10 micrometres (whole numbers: -0.0 and 0.0 are the same corner).
        return Math.round(p[3 * v] * 1e5) + " " + Math.round(p[3 * v + 1] * 1e5) + " " + Math.round(p[3 * v + 2] * 1e5);
    }

    private static float[] box(TriangleMesh m) {
        float[] b = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        float[] p = m.positions();
        for (int v = 0; v < m.vertexCount(); v++) {
            for (int k = 0; k < 3; k++) {
                b[k] = Math.min(b[k], p[3 * v + k]);
                b[k + 3] = Math.max(b[k + 3], p[3 * v + k]);
            }
        }
        return b;
    }

    private static Set<String> materials(TriangleMesh m) {
        Set<String> s = new HashSet<>();
        for (TriangleMesh.Part p : m.parts()) s.add(p.material());
        return s;
    }
}
