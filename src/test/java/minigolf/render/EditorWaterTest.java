package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import minigolf.editor.Brush;
import minigolf.editor.ChangeSet;
import minigolf.editor.CourseEditor;
import minigolf.editor.CourseWater;
import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * The editor's brush lowering ground below zero shows water at once, in the middle of the stroke:
 * the path EditorApp takes for each dab (the terrain region updated, the water rebuilt), off-screen.
 */
class EditorWaterTest {
    static final int W = 480, H = 320;

    @Test
    void groundLoweredBelowZeroIsWaterAtOnce() {
        CourseEditor editor = CourseEditor.create("pit", 4, 4, 0.1, null); // flat at 0.1
        World dry = editor.world();
        OrbitCamera cam = OrbitCamera.topDown(dry.course(), dry.terrain(), new Vector3f(0, 0, 0), (float) W / H);
        Path png = TestCourses.screenshotDir().resolve("editor-water.png");
        try (Offscreen off = new Offscreen(W, H, 0);
             SceneRenderer r = new SceneRenderer(dry.course(), dry.terrain(), TerrainMesh.ColorMode.GREEN)) {
            assertFalse(r.waterPass().hasWater());
            editor.takeChanges();
            // A stroke still going on: four dabs of 0.1 m at the centre take it to about -0.3.
            editor.beginStroke(Brush.LOWER, 0, 0, 0.6, 0.1);
            for (int i = 0; i < 3; i++) editor.dab(0, 0);
            assertTrue(editor.isStroking());
            ChangeSet changes = editor.takeChanges();
            assertTrue(changes.hasNodes());
            World w = editor.world();
            assertTrue(w.terrain().height(0, 0) < -0.2, "lowered: " + w.terrain().height(0, 0));
            int[] range = changes.nodeRange();
            r.terrainPass().updateRegion(w.course(), w.terrain(), editor.course().nodeX(range[0]) - 0.2,
                    editor.course().nodeY(range[1]) - 0.2, editor.course().nodeX(range[2]) + 0.2, editor.course().nodeY(range[3]) + 0.2);
            assertTrue(CourseWater.anyBelowZero(editor.course(), range), "EditorApp rebuilds the water for this dab");
            r.updateWater(w.course(), w.terrain());
            assertTrue(r.waterPass().hasWater(), "water before the stroke ends");
            off.bind();
            r.render(cam, W, H, 0f);
            off.savePng(png);
        }
        Pixels px = Pixels.read(png);
        float[] c = cam.project(new Vector3f(0, 0, 0), W, H);
        int x = Math.round(c[0]), y = Math.round(c[1]);
        assertTrue(px.b(x, y) > px.r(x, y) + 30 && px.b(x, y) > px.g(x, y), "water, not a brown pit: " + px.describe(x, y));
        assertFalse(CourseWater.anyBelowZero(editor.course(), new int[]{0, 0, 3, 3}), "a dry corner");
    }
}
