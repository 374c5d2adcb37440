package minigolf.course;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Segments: signed side and point-to-segment distance against hand-worked values. */
class SegmentsTest {
    @Test
    void sideIsTwiceTheSignedAreaLeftPositive() {
        assertEquals(4, Segments.side(0, 0, 2, 0, 1, 2), 0);   // left of a->b: base 2, height 2
        assertEquals(-4, Segments.side(0, 0, 2, 0, 1, -2), 0); // right
        assertEquals(0, Segments.side(0, 0, 2, 0, 5, 0), 0);   // on the line, beyond b
    }

    @Test
    void distanceIsToTheNearestPointOfTheSegment() {
        assertEquals(3, Segments.distance(1, 3, 0, 0, 2, 0), 1e-15);     // above the middle
        assertEquals(5, Segments.distance(-3, 4, 0, 0, 2, 0), 1e-15);    // beyond a: to a (3-4-5)
        assertEquals(Math.sqrt(2), Segments.distance(3, 1, 0, 0, 2, 0), 1e-15); // beyond b: to b
        assertEquals(5, Segments.distance(3, 4, 0, 0, 0, 0), 1e-15);     // a segment of no length: to a
    }
}
