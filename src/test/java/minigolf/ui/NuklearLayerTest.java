package minigolf.ui;

import java.nio.ByteBuffer;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.system.MemoryUtil.*;

/**
 * The Nuklear layer off-screen (a hidden window or an EGL context, no input from a window): it draws
 * a button in the theme's colour, a click through its input API presses a button once, and it takes
 * the keyboard only while a text field is edited.
 */
class NuklearLayerTest {
    private static final int W = 360, H = 240;
    private UiTestWindow ui;

    @BeforeEach
    void open() {
        ui = new UiTestWindow("nuklear test", W, H, 0f, 0f, 1f);
    }

    @AfterEach
    void close() {
        ui.close();
    }

    private static void panel(Runnable content) {
        Gui.setNextWindowPos(20, 20, GuiCond.Always);
        Gui.setNextWindowSize(300, 180);
        Gui.begin("Test panel##test", GuiWindowFlags.NoCollapse);
        content.run();
        Gui.end();
    }

    @Test
    void aButtonIsDrawnInTheThemeColourOverTheWindow() {
        float[] rect = new float[4];
        for (int i = 0; i < 3; i++) {
            ui.frame(() -> panel(() -> {
                Gui.button("Play", 200, 40);
                System.arraycopy(Gui.lastItemRect(), 0, rect, 0, 4);
            }));
        }
        ByteBuffer pixels = memAlloc(W * H * 4);
        try {
            ui.target.readPixels(pixels);
            assertTrue(rect[2] == 200 && rect[3] == 40, "the button's rectangle: " + java.util.Arrays.toString(rect));
            int bx = (int) rect[0] + 8, by = (int) (rect[1] + rect[3] / 2);
            int[] button = rgb(pixels, bx, by);
            for (int c = 0; c < 3; c++) {
                assertEquals(Theme.BUTTON[c], button[c], 3, "button colour at (" + bx + ", " + by + "): " + java.util.Arrays.toString(button));
            }
            int[] below = rgb(pixels, bx, (int) (rect[1] + rect[3] + 20));
            assertNotEquals(java.util.Arrays.toString(button), java.util.Arrays.toString(below), "window background differs");
            assertTrue(below[2] < 80, "the window covers the blue clear colour: " + java.util.Arrays.toString(below));
            int[] outside = rgb(pixels, 5, 5);
            assertArrayEquals(new int[]{0, 0, 255}, outside, "outside the window: the clear colour");
            // The label's text is drawn: light pixels in the button's middle.
            int light = 0;
            for (int x = (int) rect[0]; x < rect[0] + rect[2]; x++) if (rgb(pixels, x, by)[0] > 180) light++;
            assertTrue(light > 2, "label pixels on the button's middle row: " + light);
        } finally {
            memFree(pixels);
        }
    }

    /** Pixel (x, y) with y from the top, as the interface counts. */
    private static int[] rgb(ByteBuffer pixels, int x, int y) {
        int i = 4 * ((H - 1 - y) * W + x);
        return new int[]{pixels.get(i) & 0xff, pixels.get(i + 1) & 0xff, pixels.get(i + 2) & 0xff};
    }

    @Test
    void aClickOnTheButtonPressesItExactlyOnce() {
        AtomicInteger presses = new AtomicInteger();
        float[] rect = new float[4];
        Runnable widgets = () -> panel(() -> {
            Gui.text("Press the button");
            if (Gui.button("Hit", 120, 0)) presses.incrementAndGet();
            System.arraycopy(Gui.lastItemRect(), 0, rect, 0, 4);
        });
        ui.frame(widgets);
        ui.frame(widgets);
        float cx = rect[0] + rect[2] / 2, cy = rect[1] + rect[3] / 2;
        ui.layer.mouseMove(5, 5); // outside: not the interface's
        assertFalse(ui.layer.wantsMouse());
        ui.layer.mouseMove(cx, cy);
        assertTrue(ui.layer.wantsMouse(), "the pointer is over the window");
        ui.frame(widgets);
        assertEquals(0, presses.get(), "hovering is not pressing");
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false); // a quick click: both in one frame's events
        for (int i = 0; i < 5; i++) ui.frame(widgets);
        assertEquals(1, presses.get(), "one click, one press");
        // A click beside the button presses nothing.
        ui.layer.mouseMove(rect[0] + rect[2] + 30, cy);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.frame(widgets);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        for (int i = 0; i < 3; i++) ui.frame(widgets);
        assertEquals(1, presses.get());
    }

    @Test
    void aButtonIsNeverNarrowerThanItsLabel() {
        // The final card's "Watch hole" buttons were 24 pixels wide: holes 10 to 18 all showed "1".
        float[] narrow = new float[4], wide = new float[4];
        ui.frame(() -> panel(() -> {
            Gui.button("18##watch", 24, 0);
            System.arraycopy(Gui.lastItemRect(), 0, narrow, 0, 4);
            Gui.button("Next hole", 160, 0);
            System.arraycopy(Gui.lastItemRect(), 0, wide, 0, 4);
        }));
        assertTrue(narrow[2] >= Gui.buttonWidth("18"), "the button takes its label's width: " + narrow[2]);
        assertTrue(Gui.buttonWidth("18") > 24, "two digits do not fit 24 pixels");
        assertEquals(160, wide[2], 0.5, "a button wider than its label keeps its width");
    }

    @Test
    void aClickOnASlidersTrackMovesItThere() {
        // Nuklear moves a slider only by dragging its knob: the new-game players slider ignored clicks.
        int[] players = {2};
        float[] rect = new float[4];
        Runnable widgets = () -> panel(() -> {
            Gui.setNextItemWidth(200);
            Gui.sliderInt("Players", players, 1, 4);
            System.arraycopy(Gui.lastItemRect(), 0, rect, 0, 4);
        });
        ui.frame(widgets);
        ui.frame(widgets);
        float cy = rect[1] + rect[3] / 2;
        for (float[] click : new float[][]{{0.97f, 4}, {0.03f, 1}, {0.6f, 3}}) {
            ui.layer.mouseMove(rect[0] + click[0] * rect[2], cy);
            ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
            ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
            for (int i = 0; i < 3; i++) ui.frame(widgets);
            assertEquals((int) click[1], players[0], "a click at " + click[0] + " of the track");
        }
    }

    @Test
    void theKeyboardIsTheInterfacesOnlyWhileATextFieldIsEdited() {
        GuiString name = new GuiString("Ann", 32);
        GuiDouble speed = new GuiDouble(1.5);
        boolean[] deactivated = new boolean[1];
        float[] field = new float[4];
        Runnable widgets = () -> panel(() -> {
            Gui.inputText("Name", name);
            System.arraycopy(Gui.lastItemRect(), 0, field, 0, 4);
            if (Gui.isItemDeactivatedAfterEdit()) deactivated[0] = true;
            Gui.inputDouble("Speed", speed);
            if (Gui.button("OK")) {
                // nothing: a widget after the fields
            }
        });
        ui.frame(widgets);
        ui.frame(widgets);
        assertFalse(ui.layer.wantsKeyboard(), "no field edited: ESC and shortcuts are the game's");
        ui.layer.mouseMove(field[0] + field[2] - 4, field[1] + field[3] / 2);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertTrue(ui.layer.wantsKeyboard(), "the name field is edited");
        ui.layer.key(GLFW_KEY_END, true, 0);
        ui.layer.key(GLFW_KEY_END, false, 0);
        ui.layer.typeChar('e');
        ui.frame(widgets);
        ui.frame(widgets);
        assertEquals("Anne", name.get());
        assertTrue(ui.layer.wantsKeyboard());
        assertFalse(deactivated[0]);
        ui.layer.key(GLFW_KEY_ENTER, true, 0);
        ui.layer.key(GLFW_KEY_ENTER, false, 0);
        ui.frame(widgets);
        ui.frame(widgets);
        assertFalse(ui.layer.wantsKeyboard(), "Enter ends the edit");
        assertTrue(deactivated[0], "and says the field was changed");
        // A click on the field, then a click on the 3D view (outside every window), also ends it.
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertTrue(ui.layer.wantsKeyboard());
        ui.layer.mouseMove(W - 5, H - 5);
        assertFalse(ui.layer.wantsMouse(), "the pointer is off the interface");
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertFalse(ui.layer.wantsKeyboard());
        assertEquals(1.5, speed.get());
        // ESC lets go of the field too (and reaches the game from the next event on).
        ui.layer.mouseMove(field[0] + 10, field[1] + field[3] / 2);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertTrue(ui.layer.wantsKeyboard());
        ui.layer.key(GLFW_KEY_ESCAPE, true, 0);
        ui.layer.key(GLFW_KEY_ESCAPE, false, 0);
        ui.frame(widgets);
        ui.frame(widgets);
        assertFalse(ui.layer.wantsKeyboard(), "ESC ends the edit");
    }

    @Test
    void backgroundLinesGoBehindWindowsAndAWindowTakesItsContentsSize() {
        Runnable widgets = () -> {
            GuiDrawList dl = Gui.getBackgroundDrawList();
            dl.addLine(10, 50, 350, 50, 0xFF0000FF, 5f); // ABGR: opaque red, under the window at x < ~200
            dl.addLine(10, 200, 350, 200, 0xFF0000FF, 5f);
            Gui.setNextWindowPos(20, 20, GuiCond.Always);
            Gui.begin("##auto", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
            Gui.button("A wide button", 150, 0);
            Gui.text("and a line of text");
            Gui.end();
        };
        for (int i = 0; i < 3; i++) ui.frame(widgets);
        // The window fits its content: a 150-pixel button and padding, two rows.
        assertTrue(ui.layer.overInterface(20 + 160, 30));
        assertFalse(ui.layer.overInterface(20 + 230, 30), "no wider than its content");
        assertTrue(ui.layer.overInterface(30, 20 + 50));
        assertFalse(ui.layer.overInterface(30, 20 + 130), "no taller than its content");
        ByteBuffer pixels = memAlloc(W * H * 4);
        try {
            ui.target.readPixels(pixels);
            int[] free = rgb(pixels, 300, 200), open = rgb(pixels, 300, 50), covered = rgb(pixels, 60, 50);
            assertTrue(free[0] > 200 && free[1] < 60 && free[2] < 60, "a red line: " + java.util.Arrays.toString(free));
            assertTrue(open[0] > 200 && open[2] < 60, "beside the window: " + java.util.Arrays.toString(open));
            assertTrue(covered[0] < 100, "under the window the line is hidden: " + java.util.Arrays.toString(covered));
        } finally {
            memFree(pixels);
        }
    }

    @Test
    void aComboOpensOnAClickAndAClickOnAnItemChoosesIt() {
        GuiInt kind = new GuiInt(0);
        boolean[] changed = new boolean[1];
        float[] box = new float[4];
        Runnable widgets = () -> panel(() -> {
            if (Gui.combo("Kind", kind, new String[]{"Human", "Bot", "Robot"})) changed[0] = true;
            System.arraycopy(Gui.lastItemRect(), 0, box, 0, 4);
        });
        ui.frame(widgets);
        ui.frame(widgets);
        assertEquals(1, ui.layer.interfaceRects().size(), "the window only");
        ui.layer.mouseMove(box[0] + box[2] / 2, box[1] + box[3] / 2);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertEquals(2, ui.layer.interfaceRects().size(), "the list is open");
        float[] list = ui.layer.interfaceRects().get(1);
        assertTrue(list[1] >= box[1] + box[3] - 1, "below the box: " + java.util.Arrays.toString(list));
        float pad = ui.layer.context().style().window().combo_padding().y(), gap = ui.layer.context().style().window().spacing().y();
        float itemY = list[1] + pad + (Gui.frameHeight() + gap) + Gui.frameHeight() / 2; // the second item's middle
        ui.layer.mouseMove(list[0] + list[2] / 2, itemY);
        assertTrue(ui.layer.wantsMouse(), "the open list is the interface's, also outside its window");
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        for (int i = 0; i < 3; i++) ui.frame(widgets);
        assertEquals(1, kind.get(), "Bot chosen");
        assertTrue(changed[0]);
        assertEquals(1, ui.layer.interfaceRects().size(), "the list closed");
    }

    @Test
    void aMenuOfTheMainMenuBarOpensAndItsItemIsChosenOnce() {
        AtomicInteger saves = new AtomicInteger();
        float[] title = new float[4];
        Runnable widgets = () -> {
            if (Gui.beginMainMenuBar()) {
                boolean open = Gui.beginMenu("File");
                System.arraycopy(Gui.lastItemRect(), 0, title, 0, 4);
                if (open) {
                    if (Gui.menuItem("Save", "Ctrl+S")) saves.incrementAndGet();
                    Gui.menuItem("Undo", "Ctrl+Z", false, false);
                    Gui.endMenu();
                }
                Gui.endMainMenuBar();
            }
        };
        ui.frame(widgets);
        ui.frame(widgets);
        float[] bar = ui.layer.interfaceRects().get(0);
        assertEquals(0, bar[0]);
        assertEquals(0, bar[1]);
        assertEquals(W, bar[2], "across the top");
        ui.layer.mouseMove(12, bar[3] / 2); // on "File"
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        ui.frame(widgets);
        ui.frame(widgets);
        assertEquals(2, ui.layer.interfaceRects().size(), "the menu is open");
        float[] menu = ui.layer.interfaceRects().get(1);
        float pad = ui.layer.context().style().window().menu_padding().y();
        ui.layer.mouseMove(menu[0] + 20, menu[1] + pad + Gui.frameHeight() / 2); // on "Save"
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, true);
        ui.layer.mouseButton(GLFW_MOUSE_BUTTON_LEFT, false);
        for (int i = 0; i < 3; i++) ui.frame(widgets);
        assertEquals(1, saves.get());
        assertEquals(1, ui.layer.interfaceRects().size(), "the menu closed");
    }
}
