package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.api.Test;

/** Name tags over balls side by side at the tee: none covers another, the current player's stays put. */
class NameTagLayoutTest {
    @Test
    void tagsFarApartStayOverTheirBalls() {
        float[] y = {300, 310};
        assertArrayEquals(y, NameTagLayout.place(new float[]{100, 400}, y, new float[]{60, 60}, new float[]{20, 20}, 0));
    }

    @Test
    void threeTagsOverBallsTwentyPixelsApartAreStackedTheCurrentOneKeptInPlace() {
        // The windmill hole's tee as a player saw it: Ann's, Bob's and Cy's tags overlapped.
        float[] x = {640, 664, 690}, y = {470, 462, 454}, w = {44, 44, 34}, h = {24, 24, 24};
        float[] placed = NameTagLayout.place(x, y, w, h, 1); // Bob to play
        assertEquals(462, placed[1], 0, "the current player's tag stays over its ball");
        assertEquals(462 - 24 - NameTagLayout.GAP, placed[0], 1e-4, "Ann's rises just above Bob's");
        assertEquals(462 - 24 - NameTagLayout.GAP, placed[2], 1e-4, "Cy's too, beside Ann's (50 px apart: room for both)");
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < i; j++) {
                assertFalse(NameTagLayout.overlap(x[i], placed[i], w[i], h[i], x[j], placed[j], w[j], h[j]), i + " and " + j);
            }
            assertEquals(true, placed[i] <= y[i], "a tag only ever rises");
        }
    }
}
