package minigolf.editor.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.course.TerrainSpec;
import minigolf.editor.CourseEditor;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The real editor window under Xvfb: key presses go through the same path as the keyboard
 * ({@link EditorApp#onKey}), CTRL+S saves, and the saved file loads with exactly the changes made.
 */
@minigolf.render.NeedsDisplay
class EditorAppTest {
    @TempDir
    Path dir;

    @Test
    void keyboardEditsAreSavedAndLoadBack() throws Exception {
        Path file = dir.resolve("course.json");
        CourseEditor start = CourseEditor.create("keys", 8, 4, 0.1, null); // 81 x 41 nodes, flat at 0.1, tool at (0, 0)
        start.saveAs(file);
        List<int[]> keys = Arrays.stream(("D,D,D,D,D,ENTER,"     // tool to (0.5, 0); raise brush there
                + "SHIFT,M,ENTER,"                                 // object tool, wall, place: (0, 0)-(1, 0)
                + "B,W,W,W,W,W,ENTER,"                             // tree at (0.5, 0.5)
                + "SHIFT,P,CTRL+Z,A,P,"                            // delete cell (45, 25), undo, delete cell (44, 25)
                + "CTRL+S").split(",")).map(EditorApp::parseKey).toList();
        Path shot = dir.resolve("editor.png");
        EditorApp app = new EditorApp(CourseEditor.open(file),
                new EditorApp.Options(shot, keys.size() + 2, keys, dir.resolve("config"), false));
        CourseEditor after = app.run();
        assertFalse(after.isDirty(), "CTRL+S saved the course");

        Course saved = World.load(file).course();
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) saved.terrain();
        assertEquals(0.15, g.heights()[20][45], 1e-12, "the raise brush's centre: +strength 0.05");
        assertEquals(0.1, g.heights()[20][30], 0, "outside the brush");
        assertEquals(2, saved.obstacles().size());
        Obstacle.Wall wall = (Obstacle.Wall) saved.obstacles().get(0);
        assertEquals(0, wall.from().x(), 1e-9);
        assertEquals(1, wall.to().x(), 1e-9);
        assertEquals(0, wall.from().y(), 1e-9);
        Obstacle.Tree tree = (Obstacle.Tree) saved.obstacles().get(1);
        assertEquals(0.5, tree.position().x(), 1e-9);
        assertEquals(0.5, tree.position().y(), 1e-9);
        assertEquals(1, g.deletedCount());
        assertTrue(g.isDeleted(44, 25));
        assertEquals(saved, after.toCourse());

        // The screenshot shows the course: mostly not the clear colour.
        BufferedImage img = ImageIO.read(shot.toFile());
        assertEquals(1400, img.getWidth());
        int green = 0;
        for (int y = 0; y < img.getHeight(); y += 8) {
            for (int x = 0; x < img.getWidth(); x += 8) {
                int rgb = img.getRGB(x, y), r = (rgb >> 16) & 255, gr = (rgb >> 8) & 255, b = rgb & 255;
                if (gr > r + 20 && gr > b + 20) green++;
            }
        }
        assertTrue(green > 2000, "grass pixels: " + green);
    }
}
