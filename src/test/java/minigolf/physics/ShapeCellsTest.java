package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import minigolf.course.Shape;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** Cell shapes (the classic tracks' pixel areas) in the engine: their box and where a path first enters them. */
class ShapeCellsTest {
    // A 10 x 10 grid of 0.1 m cells from (0, 0): row 5, columns 3 to 5; row 8, column 9.
    static final Shape.Cells CELLS = new Shape.Cells(new Vec2(0, 0), 0.1, 10, 10, new int[] {5, 3, 6, 8, 9, 10});

    @Test
    void theBoxHoldsTheSetCellsOnly() {
        assertArrayEquals(new double[] {0.3, 0.5, 1.0, 0.9}, ShapeBoxes.of(CELLS), 1e-12);
        assertArrayEquals(new double[] {0, 0, 0, 0}, ShapeBoxes.of(new Shape.Cells(new Vec2(0, 0), 0.1, 4, 4, new int[0])), 0);
    }

    @Test
    void aSegmentEntersAtTheFirstSetCellOnItsWay() {
        // Along y = 0.55 from x = 0 to 1: the cell (3, 5) begins at x = 0.3.
        assertEquals(0.3, ShapeCrossing.firstEntry(CELLS, 0, 0.55, 1, 0.55), 1e-12);
        // Back from the right: (5, 5) ends at x = 0.6, a quarter of the way from 1.4 to -0.2.
        assertEquals(0.5, ShapeCrossing.firstEntry(CELLS, 1.4, 0.55, -0.2, 0.55), 1e-12);
        // The diagonal (0, 0) to (1, 1) passes (3, 3), (4, 4), then (5, 5) at 0.5: the first set cell.
        assertEquals(0.5, ShapeCrossing.firstEntry(CELLS, 0, 0, 1, 1), 1e-12);
        // Starting inside: 0. Through unset cells only, or outside the grid: none.
        assertEquals(0, ShapeCrossing.firstEntry(CELLS, 0.35, 0.55, 0, 0));
        assertEquals(Double.POSITIVE_INFINITY, ShapeCrossing.firstEntry(CELLS, 0, 0.25, 1, 0.25));
        assertEquals(Double.POSITIVE_INFINITY, ShapeCrossing.firstEntry(CELLS, -1, -1, -0.5, 2));
        // Entering the grid from outside, straight into a set cell on its edge: (9, 8) at x = 1.0 from x = 1.5.
        assertEquals(0.5, ShapeCrossing.firstEntry(CELLS, 1.5, 0.85, 0.5, 0.85), 1e-12);
        // A segment that stops short of it.
        assertEquals(Double.POSITIVE_INFINITY, ShapeCrossing.firstEntry(CELLS, 0, 0.55, 0.29, 0.55));
    }
}
