package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import minigolf.course.Bounds;
import org.junit.jupiter.api.Test;

/** The terrain cells the balls' shadows redraw (plain arithmetic, no GL). */
class CellRangeTest {
    /** A 4 m x 2 m course in 40 x 20 cells of 0.1 m. */
    private static final Bounds COURSE = new Bounds(-2, -1, 2, 1);

    @Test
    void theCellsUnderABoxAndOneMoreEachWay() {
        // x 0.23..0.31 m is cells 22.3..23.1 from the left edge: cells 22 and 23; y -0.05..0.05 is 9.5..10.5: 9 and 10.
        float[] box = {0.23f, -0.05f, 0f, 0.31f, 0.05f, 0.2f};
        assertEquals(new CellRange(22, 24, 9, 11, false), CellRange.of(COURSE, 40, 20, box, 0));
        assertEquals(new CellRange(21, 25, 8, 12, false), CellRange.of(COURSE, 40, 20, box, 1));
    }

    @Test
    void clippedToTheGridAndTheEdgeSeen() {
        // Past the south-west corner: clipped to cell 0, and the skirts may show.
        float[] corner = {-2.3f, -1.2f, 0f, -1.95f, -0.93f, 0.1f};
        assertEquals(new CellRange(0, 2, 0, 2, true), CellRange.of(COURSE, 40, 20, corner, 1));
        // Touching the north edge from inside counts as reaching it.
        float[] north = {0.05f, 0.93f, 0f, 0.15f, 1f, 0.1f};
        CellRange n = CellRange.of(COURSE, 40, 20, north, 0);
        assertEquals(new CellRange(20, 22, 19, 20, true), n);
        assertTrue(n.hasRows());
    }

    @Test
    void aBoxBesideTheCourseHasNoRows() {
        // Wholly north of the course: rows from 21 clipped to 20, none left, but the edge is reached.
        float[] beyond = {0f, 1.1f, 0f, 0.1f, 1.3f, 0.1f};
        CellRange r = CellRange.of(COURSE, 40, 20, beyond, 0);
        assertFalse(r.hasRows());
        assertTrue(r.edge());
    }
}
