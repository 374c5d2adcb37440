package minigolf.editor.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.Shape;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** "Entry to tool" and "Zone to tool" move a cell shape (an imported classic teleport or push zone) whole. */
class MovedShapeTest {
    @Test
    void cellsMoveWithTheirGridTheBoxCentreToTheTool() {
        // Cells (2, 1) and (3, 1) of a 0.5 m grid from (-1, -1): box x 0 to 1, y -0.5 to 0, centre (0.5, -0.25).
        Shape.Cells cells = new Shape.Cells(new Vec2(-1, -1), 0.5, 8, 8, new int[] {1, 2, 4});
        Shape.Cells moved = (Shape.Cells) ElementPanels.ObjectsText.moved(cells, 3, 2);
        assertEquals(new Vec2(1.5, 1.25), moved.origin());
        assertEquals(cells.spanCount(), moved.spanCount());
        assertTrue(moved.contains(3, 2) && moved.contains(2.6, 1.8) && !moved.contains(3.6, 2));
    }
}
