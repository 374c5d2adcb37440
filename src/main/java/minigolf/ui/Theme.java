package minigolf.ui;

import org.lwjgl.nuklear.NkColor;
import org.lwjgl.nuklear.NkContext;
import org.lwjgl.nuklear.NkStyle;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.nuklear.Nuklear.*;

/** A calm green-and-cream look for the menus and the HUD, readable over the course. */
public final class Theme {
    /** RGBA 0-255: the colours the tests check pixels against. */
    public static final int[] WINDOW = {18, 31, 23, 230};
    public static final int[] BUTTON = {46, 115, 66, 255};
    public static final int[] BUTTON_HOVER = {64, 148, 84, 255};
    public static final int[] BUTTON_ACTIVE = {77, 173, 97, 255};
    public static final int[] TEXT = {245, 242, 224, 255};
    static final int[] FIELD = {36, 56, 41, 255};
    static final int[] HEADER = {33, 89, 51, 255};
    static final int[] BORDER = {70, 110, 80, 255};
    static final int[] ACCENT = {230, 179, 51, 255};
    static final int[] DISABLED_TEXT = {150, 150, 140, 255};

    private Theme() {
    }

    static void apply(NkContext ctx, float scale) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkColor.Buffer table = NkColor.malloc(NK_COLOR_COUNT, stack);
            set(table, NK_COLOR_TEXT, TEXT);
            set(table, NK_COLOR_WINDOW, WINDOW);
            set(table, NK_COLOR_HEADER, HEADER);
            set(table, NK_COLOR_BORDER, BORDER);
            set(table, NK_COLOR_BUTTON, BUTTON);
            set(table, NK_COLOR_BUTTON_HOVER, BUTTON_HOVER);
            set(table, NK_COLOR_BUTTON_ACTIVE, BUTTON_ACTIVE);
            set(table, NK_COLOR_TOGGLE, new int[]{75, 110, 85, 255}); // the box shows on the dark window
            set(table, NK_COLOR_TOGGLE_HOVER, new int[]{95, 135, 105, 255});
            set(table, NK_COLOR_TOGGLE_CURSOR, ACCENT);
            set(table, NK_COLOR_SELECT, FIELD);
            set(table, NK_COLOR_SELECT_ACTIVE, BUTTON);
            set(table, NK_COLOR_SLIDER, FIELD);
            set(table, NK_COLOR_SLIDER_CURSOR, BUTTON_HOVER);
            set(table, NK_COLOR_SLIDER_CURSOR_HOVER, BUTTON_ACTIVE);
            set(table, NK_COLOR_SLIDER_CURSOR_ACTIVE, new int[]{95, 195, 115, 255});
            set(table, NK_COLOR_PROPERTY, FIELD);
            set(table, NK_COLOR_EDIT, FIELD);
            set(table, NK_COLOR_EDIT_CURSOR, TEXT);
            set(table, NK_COLOR_COMBO, FIELD);
            set(table, NK_COLOR_CHART, FIELD);
            set(table, NK_COLOR_CHART_COLOR, ACCENT);
            set(table, NK_COLOR_CHART_COLOR_HIGHLIGHT, ACCENT);
            set(table, NK_COLOR_SCROLLBAR, new int[]{25, 40, 30, 255});
            set(table, NK_COLOR_SCROLLBAR_CURSOR, BUTTON);
            set(table, NK_COLOR_SCROLLBAR_CURSOR_HOVER, BUTTON_HOVER);
            set(table, NK_COLOR_SCROLLBAR_CURSOR_ACTIVE, BUTTON_ACTIVE);
            set(table, NK_COLOR_TAB_HEADER, HEADER);
            nk_style_from_table(ctx, table);
        }
        NkStyle s = ctx.style();
        s.window().padding().set(14 * scale, 12 * scale);
        s.window().spacing().set(10 * scale, 6 * scale); // the settings form fits a 720-pixel-high window
        s.window().rounding(8 * scale);
        s.window().border(1);
        s.window().header().padding().set(10 * scale, 4 * scale);
        s.window().header().label_padding().set(2 * scale, 2 * scale);
        s.window().popup_padding().set(6 * scale, 6 * scale);
        s.window().combo_padding().set(6 * scale, 6 * scale);
        s.window().menu_padding().set(6 * scale, 6 * scale);
        s.window().tooltip_padding().set(8 * scale, 6 * scale);
        s.window().min_row_height_padding(2 * scale);
        s.button().rounding(5 * scale);
        s.button().padding().set(6 * scale, 3 * scale);
        s.button().border(0);
        s.edit().rounding(4 * scale);
        s.edit().padding().set(4 * scale, 3 * scale);
        s.combo().rounding(4 * scale);
        s.slider().rounding(4 * scale);
        s.progress().rounding(4 * scale);
        s.progress().cursor_rounding(4 * scale);
        s.progress().padding().set(2 * scale, 2 * scale);
        s.progress().cursor_normal().data().color().set((byte) ACCENT[0], (byte) ACCENT[1], (byte) ACCENT[2], (byte) ACCENT[3]);
        s.progress().cursor_hover().data().color().set((byte) ACCENT[0], (byte) ACCENT[1], (byte) ACCENT[2], (byte) ACCENT[3]);
        s.progress().cursor_active().data().color().set((byte) ACCENT[0], (byte) ACCENT[1], (byte) ACCENT[2], (byte) ACCENT[3]);
        s.checkbox().padding().set(3 * scale, 3 * scale);
        s.option().padding().set(3 * scale, 3 * scale);
        s.menu_button().padding().set(6 * scale, 3 * scale);
        s.contextual_button().padding().set(6 * scale, 3 * scale);
    }

    private static void set(NkColor.Buffer table, int index, int[] rgba) {
        table.get(index).set((byte) rgba[0], (byte) rgba[1], (byte) rgba[2], (byte) rgba[3]);
    }
}
