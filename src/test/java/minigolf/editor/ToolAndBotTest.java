package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.game.BotCatalog;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The keyboard scheme (headless), terrain picking and "Ask a bot". */
class ToolAndBotTest {
    @Test
    void theOriginalKeysMoveTheToolPlaceAndDelete() {
        CourseEditor e = EditorOperationsTest.flat();
        ToolController t = new ToolController(e);
        assertEquals(0, t.x(), 0);
        assertEquals(ToolController.Mode.TERRAIN, t.mode());
        for (int k = 0; k < 3; k++) t.press(EditorKey.RIGHT);
        t.press(EditorKey.UP);
        assertEquals(0.3, t.x(), 1e-12);
        assertEquals(0.1, t.y(), 1e-12);
        t.press(EditorKey.PLACE); // raise brush, 0.05 at the centre
        assertEquals(0.15, e.course().height(43, 21), 1e-12);
        assertEquals("object tool: wall", t.press(EditorKey.TOGGLE_TOOL));
        assertEquals("placed wall", t.press(EditorKey.PLACE));
        assertEquals("object tool: tree", t.press(EditorKey.TREE));
        t.press(EditorKey.DOWN);
        t.press(EditorKey.DOWN);
        t.press(EditorKey.PLACE);
        assertTrue(e.course().obstacles().get(1) instanceof Obstacle.Tree);
        Vec2 tree = ((Obstacle.Tree) e.course().obstacles().get(1)).position();
        assertEquals(0.3, tree.x(), 1e-12);
        assertEquals(-0.1, tree.y(), 1e-12);
        t.press(EditorKey.ROTATE_LEFT);
        assertEquals("deleted tree", t.press(EditorKey.DELETE));
        assertEquals(1, e.course().obstacles().size());
        assertEquals(0, e.obstacleNear(t.x(), t.y(), ToolController.PICK_DISTANCE), "the wall 0.2 m away is under the tool");
        for (int k = 0; k < 5; k++) t.press(EditorKey.DOWN);
        assertEquals("no object under the tool", t.press(EditorKey.DELETE));
        // The terrain tool's P deletes the cell whose lower-left corner is the tool's node: (43, 14).
        t.press(EditorKey.TOGGLE_TOOL);
        assertEquals("deleted cell (43, 14)", t.press(EditorKey.DELETE));
        assertTrue(e.course().isDeleted(43, 14));
        assertEquals("restored cell (43, 14)", t.press(EditorKey.DELETE));
        assertEquals("undid restore cell", t.press(EditorKey.UNDO));
        assertTrue(e.course().isDeleted(43, 14));
        assertEquals("redid restore cell", t.press(EditorKey.REDO));
        // The tool stays on the grid.
        for (int k = 0; k < 100; k++) t.press(EditorKey.LEFT);
        assertEquals(-4, t.x(), 1e-12);
        // A bad placement is a message, not an exception.
        t.setAction(ToolController.TerrainAction.SET_HEIGHT);
        t.typedHeight = Double.NaN;
        assertEquals("height must be a finite number", t.press(EditorKey.PLACE));
    }

    @Test
    void pickingFindsWhereARayMeetsTheTerrain() {
        CourseEditor e = CourseEditor.create("slope", 8, 4, 0.1, "0.5 + 0.1*x");
        World w = e.world();
        double[] down = TerrainPicker.pick(w.terrain(), w.bounds(), 1, 0.5, 5, 0, 0, -1, 0.05);
        assertEquals(1, down[0], 1e-12);
        assertEquals(0.6, down[2], 1e-6);
        // 45 degrees down along +x from (-3, 0, 2): meets z = 0.5 + 0.1 x where 2 - (x + 3) = 0.5 + 0.1 x, x = -1.5/1.1.
        double[] slant = TerrainPicker.pick(w.terrain(), w.bounds(), -3, 0, 2, 1, 0, -1, 0.05);
        assertEquals(-1.5 / 1.1, slant[0], 1e-6);
        assertNull(TerrainPicker.pick(w.terrain(), w.bounds(), 0, 0, 5, 0, 0, 1, 0.05), "looking up");
        assertNull(TerrainPicker.pick(w.terrain(), w.bounds(), 10, 0, 5, 1, 0, -0.1, 0.05), "outside the bounds");
    }

    @Test
    void aBotHolesAnOpenCourseAndFailsAWalledOne() throws Exception {
        CourseEditor e = EditorOperationsTest.flat();
        BotCheck check = BotCheck.start(BotCatalog.planner("straight"), e.world(), SimulationSettings.DEFAULT, 5, 1);
        check.join();
        BotCheck.Result r = check.result();
        assertTrue(r.holed(), r.describe());
        assertTrue(r.strokes() <= 2, r.describe());
        // A fence right across between start and hole: the straight putter never gets through.
        e.addObstacle(new Obstacle.Wall(new Vec2(0, -2.5), new Vec2(0, 2.5), 0.05, 0.3, 0.7));
        BotCheck.Result walled = BotCheck.play(BotCatalog.planner("straight"), e.world(), SimulationSettings.DEFAULT, 3, 1,
                new minigolf.game.ShotPlanner.Control() {
                    public void progress(double f, String m) {
                    }

                    public boolean isCancelled() {
                        return false;
                    }

                    public void whenCancelled(Runnable a) {
                    }
                });
        assertFalse(walled.holed());
        assertEquals(3, walled.strokes());
        assertEquals("straight did not hole it within 3 strokes", walled.describe());
    }
}
