package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

/** A window asked for larger than the screen (the editor's 1400 x 860 on a 1366 x 768 laptop) fits it. */
class WindowFitTest {
    @Test
    void theEditorsWindowFitsA1366x768Screen() {
        assertArrayEquals(new int[]{1366, 728}, Window.fitted(1400, 860, 1366, 768), "the title bar's 40 pixels kept");
        assertArrayEquals(new int[]{1280, 720}, Window.fitted(1280, 720, 1920, 1080), "a window that fits is left alone");
        assertArrayEquals(new int[]{1400, 860}, Window.fitted(1400, 860, 0, 0), "no work area known");
        assertArrayEquals(new int[]{320, 200}, Window.fitted(1400, 860, 100, 100), "never smaller than usable");
    }
}
