package minigolf.editor.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The editor's minimap takes a fifth of the window but stops 8 px above the Course panel. */
class MinimapPlacementTest {
    @Test
    void aFifthOfTheWindowWhereThePanelLeavesRoom() {
        assertEquals(172, EditorApp.minimapSize(1400, 860, 400)); // 860 / 5
        assertEquals(172, EditorApp.minimapSize(1400, 860, Float.MAX_VALUE)); // before the panel was drawn
    }

    @Test
    void shrinksAboveTheCoursePanelOnALaptopScreen() {
        // 1366 x 768 leaves a 1366 x 728 window; the panel's top was measured at 174 px.
        int size = EditorApp.minimapSize(1366, 728, 174);
        assertEquals(174 - EditorApp.MINIMAP_TOP - 8, size);
        assertTrue(EditorApp.MINIMAP_TOP + size + 8 <= 174, "the minimap ends above the panel");
    }

    @Test
    void neverSmallerThan64PixelsUnlessTheWindowIs() {
        assertEquals(64, EditorApp.minimapSize(1366, 728, 60));
        assertEquals(40, EditorApp.minimapSize(200, 200, 60)); // a tiny window: its fifth
    }
}
