package minigolf.ui;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.lwjgl.nuklear.NkColor;
import org.lwjgl.nuklear.NkContext;
import org.lwjgl.nuklear.NkImage;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.nuklear.Nuklear.*;

/**
 * The screens' immediate-mode interface on Nuklear, with ImGui's names and argument order (so that
 * {@code ImGui.button("Play")} reads {@code Gui.button("Play")}). Calls go to the {@link NuklearLayer}
 * whose frame is open. ImGui's flow layout is kept: each widget starts a new row unless
 * {@link #sameLine()} came before it; a window without a size takes its content's size, measured the
 * frame before (so a new window settles in its second frame). Labels "Text##id" show "Text";
 * "Text###id" also names the window "id". Edit fields, sliders and combos show their label on the right.
 */
public final class Gui {
    static final int MAX_COLUMNS = 64;

    /** What a frame leaves for input between frames: where the interface is, whether a field is edited. */
    static final class FrameResult {
        List<float[]> rects = new ArrayList<>();
        boolean textFieldActive;
    }

    static final class WindowMemory {
        float needW, needH;
        boolean measured;
    }

    /** The window being built. */
    static final class Win {
        String id;
        WindowMemory memory;
        float x, y, w, h;
        boolean rowOpen, sameLine, frameText, inMenuBar;
        float rowW, contentW, sameLineOffset;
        // Table.
        String table;
        int tableFlags, tableRow, nextColumn;
        float[] widths, measured;
        List<String> headers;
        boolean cellPending;
        float cellWidth;
        int cellColumn;
    }

    record Menu(boolean combo, String key) {
    }

    static NuklearLayer layer;
    static NkContext ctx;
    static FontAtlas font;
    static float scale = 1, textH, frameH, spacingX, itemW;
    static Win win;
    static float[] nextPos, nextSize, nextConstraints;
    static float nextItemWidth = -1;
    static final float[] lastItem = new float[4];
    static boolean lastDeactivatedAfterEdit;
    static final Deque<String> ids = new ArrayDeque<>();
    static final Deque<Menu> menus = new ArrayDeque<>();
    static final Map<String, WindowMemory> windows = new HashMap<>();
    static final Map<String, float[]> tableWidths = new HashMap<>();
    static final Map<String, float[]> menuSizes = new HashMap<>();
    static final GuiDrawList background = new GuiDrawList();
    static FrameResult building = new FrameResult();
    static long frame;
    /** ESC came since the last frame: a text field being edited lets go. */
    static boolean escape;

    private Gui() {
    }

    // ---- Frame ------------------------------------------------------------------------------------

    static void beginFrame(NuklearLayer l, boolean escapePressed) {
        escape = escapePressed;
        if (layer != l) forget();
        layer = l;
        ctx = l.context();
        font = l.font();
        scale = l.scale();
        textH = font.height();
        frameH = Math.round(font.height() + 6 * scale);
        spacingX = ctx.style().window().spacing().x();
        itemW = Math.round(10 * font.height());
        building = new FrameResult();
        win = null;
        ids.clear();
        menus.clear();
        frame++;
    }

    static void endFrame(FrameResult result) {
        if (win != null) throw new IllegalStateException("window '" + win.id + "' was not ended");
        background.flush(ctx, layer.displayWidth(), layer.displayHeight(), font);
        result.rects = building.rects;
        result.textFieldActive = building.textFieldActive;
        GuiFields.forgetUnseen(frame);
    }

    static void detach(NuklearLayer l) {
        if (layer == l) forget();
    }

    /** Drops every remembered size and field (a new layer, or the layer closed). */
    static void forget() {
        layer = null;
        ctx = null;
        windows.clear();
        tableWidths.clear();
        menuSizes.clear();
        background.clear();
        GuiFields.clear();
    }

    static long frameNumber() {
        return frame;
    }

    static FrameResult building() {
        return building;
    }

    static void requireWindow() {
        if (win == null) throw new IllegalStateException("a widget outside Gui.begin/end");
    }

    public static float displayWidth() {
        return layer.displayWidth();
    }

    public static float displayHeight() {
        return layer.displayHeight();
    }

    /** The line height of the interface font. */
    public static float textLineHeight() {
        return textH;
    }

    /** The height of a button or field. */
    public static float frameHeight() {
        return frameH;
    }

    /** The width and height of a label's plate ({@link GuiDrawList#addLabel}) round {@code text}. */
    public static float[] labelPlate(String text) {
        float pad = GuiDrawList.labelPad(font.height());
        String drawn = GuiDrawList.labelText(text, font, layer.displayWidth());
        return new float[]{font.width(drawn) + 2 + 2 * pad, font.height() + 2 * pad};
    }

    static float textWidth(String s) {
        return font.width(s);
    }

    // ---- Windows ----------------------------------------------------------------------------------

    public static void setNextWindowPos(float x, float y, int cond) {
        setNextWindowPos(x, y, cond, 0, 0);
    }

    /** Places the next window with its point (pivotX, pivotY), as fractions of its size, at (x, y). */
    public static void setNextWindowPos(float x, float y, int cond, float pivotX, float pivotY) {
        nextPos = new float[]{x, y, pivotX, pivotY};
    }

    public static void setNextWindowSize(float width, float height) {
        nextSize = new float[]{width, height};
    }

    /** Bounds for the next window's size (a content-sized window scrolls beyond the maximum). */
    public static void setNextWindowSizeConstraints(float minWidth, float minHeight, float maxWidth, float maxHeight) {
        nextConstraints = new float[]{minWidth, minHeight, maxWidth, maxHeight};
    }

    /**
     * The window being built: x, y, width and height in interface units. In the frame a window is
     * first measured it is placed off screen (negative x and y).
     */
    public static float[] windowRect() {
        if (win == null) throw new IllegalStateException("windowRect outside a window");
        return new float[]{win.x, win.y, win.w, win.h};
    }

    public static void setNextWindowSize(float width, float height, int cond) {
        setNextWindowSize(width, height);
    }

    public static boolean begin(String name) {
        return begin(name, GuiWindowFlags.None);
    }

    /** Opens a window; always pair with {@link #end()}. A zero width or height is the content's. */
    public static boolean begin(String name, int flags) {
        return GuiWindows.begin(name, flags);
    }

    public static void end() {
        GuiWindows.end();
    }

    /**
     * The size (width, height) the window {@code name} takes, as it measured its content in the
     * frames before, or null before it was first drawn (a new window measures itself off screen):
     * where one window is placed below another drawn later in the frame.
     */
    public static float[] measuredSize(String name) {
        WindowMemory m = windows.get(windowId(name));
        return m == null || !m.measured ? null : new float[]{m.needW, m.needH};
    }

    /** "Play##main" shows "Play"; "Card: A###card" shows "Card: A". */
    /** The part of a label that is shown (before "##"), fitted to the screen ({@link GuiText}). */
    static String displayLabel(String label) {
        int i = label.indexOf("##");
        return fitted(i < 0 ? label : label.substring(0, i));
    }

    static String windowId(String name) {
        int i = name.indexOf("###");
        return GuiText.id(i < 0 ? name : name.substring(i + 3));
    }

    /** Text cut short with "..." where it is wider than the screen leaves room for ({@link GuiText#fit}). */
    static String fitted(String text) {
        return GuiText.fit(text, font, maxTextWidth());
    }

    /** The widest text one widget draws: the screen less a window's padding and a margin each side. */
    static float maxTextWidth() {
        float pad = ctx == null ? 0 : ctx.style().window().padding().x();
        return Math.max(8 * textH, layer.displayWidth() - 2 * (pad + 8 * scale));
    }

    public static void pushID(int id) {
        ids.push(Integer.toString(id));
    }

    public static void pushID(String id) {
        ids.push(id);
    }

    public static void popID() {
        ids.pop();
    }

    static String idPath(String label) {
        return win.id + "/" + String.join("/", ids) + "/" + label;
    }

    // ---- Layout -----------------------------------------------------------------------------------

    /** The next widget goes on the same row as the last one. */
    public static void sameLine() {
        sameLine(0);
    }

    /** The same row, the next widget at {@code offsetFromStart} pixels from the content's left edge (0: right after). */
    public static void sameLine(float offsetFromStart) {
        requireWindow();
        win.sameLine = true;
        win.sameLineOffset = offsetFromStart;
    }

    /** Ends a row left open by {@link #sameLine()}, or leaves an empty line. */
    public static void newLine() {
        requireWindow();
        if (win.sameLine) {
            win.sameLine = false;
            win.rowOpen = false;
            return;
        }
        win.rowOpen = false;
        nk_layout_row_dynamic(ctx, textH, 1);
        nk_spacing(ctx, 1);
    }

    public static void separator() {
        requireWindow();
        win.rowOpen = false;
        win.sameLine = false;
        nk_layout_row_dynamic(ctx, Math.max(1, Math.round(2 * scale)), 1);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkRect r = NkRect.malloc(stack);
            if (nk_widget(r, ctx) != NK_WIDGET_INVALID) {
                NkColor c = colour(stack, Theme.BORDER);
                nk_fill_rect(nk_window_get_canvas(ctx), r.set(r.x(), r.y() + r.h() / 2 - scale / 2, r.w(), Math.max(1, scale)), 0, c);
            }
        }
    }

    public static void setNextItemWidth(float width) {
        nextItemWidth = width;
    }

    /** The next text line is as tall as a button, its text centred like a button's. */
    public static void alignTextToFramePadding() {
        requireWindow();
        win.frameText = true;
    }

    static float takeItemWidth() {
        float w = nextItemWidth > 0 ? nextItemWidth : itemW;
        nextItemWidth = -1;
        return w;
    }

    /** Room for the next widget: a new row, or the rest of the row after sameLine, or a table cell. */
    static void place(float w, float h) {
        requireWindow();
        lastDeactivatedAfterEdit = false;
        if (win.cellPending) {
            nk_layout_row_push(ctx, win.cellWidth);
            win.cellPending = false;
            recordItem();
            return;
        }
        if (win.sameLine && win.rowOpen) {
            float x = win.rowW + spacingX;
            float gap = win.sameLineOffset - x - spacingX;
            if (win.sameLineOffset > 0 && gap > 0) {
                nk_layout_row_push(ctx, gap);
                nk_spacing(ctx, 1);
                x += gap + spacingX;
            }
            nk_layout_row_push(ctx, w);
            win.rowW = x + w;
        } else {
            nk_layout_row_begin(ctx, NK_STATIC, h, MAX_COLUMNS);
            nk_layout_row_push(ctx, w);
            win.rowOpen = true;
            win.rowW = w;
        }
        win.sameLine = false;
        win.sameLineOffset = 0;
        win.contentW = Math.max(win.contentW, win.rowW);
        recordItem();
    }

    /** A whole-width row of its own (selectables, menu items), {@code w} wide in a window that takes its content's size. */
    static void placeFullRow(float w, float h) {
        requireWindow();
        lastDeactivatedAfterEdit = false;
        win.rowOpen = false;
        win.sameLine = false;
        nk_layout_row_dynamic(ctx, h, 1);
        win.contentW = Math.max(win.contentW, w);
        recordItem();
    }

    static void recordItem() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkRect r = nk_widget_bounds(ctx, NkRect.malloc(stack));
            lastItem[0] = r.x();
            lastItem[1] = r.y();
            lastItem[2] = r.w();
            lastItem[3] = r.h();
        }
    }

    /** The width of the last widget. */
    public static float getItemRectSizeX() {
        return lastItem[2];
    }

    /** The horizontal gap between widgets on a row. */
    public static float itemSpacingX() {
        return spacingX;
    }

    static float[] lastItemRect() {
        return lastItem;
    }

    /** The last widget's rectangle, {x, y, width, height} in the interface's pixels (a copy; tests click there). */
    public static float[] lastItemBounds() {
        return lastItem.clone();
    }

    static void setDeactivatedAfterEdit(boolean value) {
        lastDeactivatedAfterEdit = value;
    }

    /** Whether the edit field just drawn lost the keyboard after its text was changed. */
    public static boolean isItemDeactivatedAfterEdit() {
        return lastDeactivatedAfterEdit;
    }

    public static boolean isItemHovered() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            return nk_input_is_mouse_hovering_rect(ctx.input(), NkRect.malloc(stack).set(lastItem[0], lastItem[1], lastItem[2], lastItem[3]));
        }
    }

    public static void setTooltip(String text) {
        nk_tooltip(ctx, fitted(text));
    }

    public static void beginDisabled() {
        nk_widget_disable_begin(ctx);
    }

    public static void endDisabled() {
        nk_widget_disable_end(ctx);
    }

    // ---- Text and buttons -------------------------------------------------------------------------

    public static void text(String text) {
        label(text, Theme.TEXT);
    }

    public static void textColored(float r, float g, float b, float a, String text) {
        label(text, new int[]{Math.round(r * 255), Math.round(g * 255), Math.round(b * 255), Math.round(a * 255)});
    }

    public static void textDisabled(String text) {
        label(text, Theme.DISABLED_TEXT);
    }

    /** Text broken into lines at spaces to the window's width (a few lines' worth at most, then "..."). */
    public static void textWrapped(String full) {
        requireWindow();
        String text = full.length() > 4 * GuiText.MAX_CHARS ? GuiText.cut(full, 4 * GuiText.MAX_CHARS) + GuiText.ELLIPSIS : full;
        float avail;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            avail = nk_window_get_content_region(ctx, NkRect.malloc(stack)).w();
        }
        StringBuilder line = new StringBuilder();
        for (String word : text.split(" ")) {
            String candidate = line.length() == 0 ? word : line + " " + word;
            if (line.length() > 0 && font.width(candidate) > avail - 4) {
                wrappedLine(line.toString(), avail);
                line.setLength(0);
                line.append(word);
            } else {
                line.setLength(0);
                line.append(candidate);
            }
        }
        if (line.length() > 0) wrappedLine(line.toString(), avail);
    }

    static void wrappedLine(String line, float avail) {
        String s = GuiText.fit(line, font, avail); // a word wider than the window
        place(Math.min(avail, font.width(s) + 2), textH);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            nk_label_colored(ctx, s, NK_TEXT_LEFT, colour(stack, Theme.TEXT));
        }
    }

    static void label(String full, int[] rgba) {
        requireWindow();
        String text = fitted(full);
        float w = font.width(text) + 2;
        place(w, win.frameText ? frameH : textH);
        win.frameText = false;
        if (win.table != null) win.measured[win.cellColumn] = Math.max(win.measured[win.cellColumn], w);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            nk_label_colored(ctx, text, NK_TEXT_LEFT, colour(stack, rgba));
        }
    }

    public static boolean button(String label) {
        return button(label, 0, 0);
    }

    /** A button; a zero width or height fits the label. */
    public static boolean button(String label, float width, float height) {
        String shown = displayLabel(label);
        // Never narrower than its label: Nuklear clips a label that does not fit ("10" showed as "1").
        float w = width > 0 ? Math.max(width, buttonWidth(shown)) : buttonWidth(shown);
        place(w, height > 0 ? height : frameH);
        return nk_button_label(ctx, shown);
    }

    /** A square button with a minus or plus sign (the step buttons of number fields). */
    static boolean stepButton(boolean plus) {
        place(frameH, frameH);
        pushID(plus ? "+" : "-");
        boolean hit = nk_button_label(ctx, "");
        popID();
        // The sign drawn over the button: Nuklear's symbols shrink to nothing in a small button.
        float cx = lastItem[0] + lastItem[2] / 2, cy = lastItem[1] + lastItem[3] / 2, half = Math.round(textH * 0.3f);
        float t = Math.max(1, Math.round(1.5f * scale));
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var canvas = nk_window_get_canvas(ctx);
            NkColor c = colour(stack, Theme.TEXT);
            nk_fill_rect(canvas, NkRect.malloc(stack).set(cx - half, cy - t / 2, 2 * half, t), 0, c);
            if (plus) nk_fill_rect(canvas, NkRect.malloc(stack).set(cx - t / 2, cy - half, t, 2 * half), 0, c);
        }
        return hit;
    }

    static float buttonWidth(String shown) {
        var b = ctx.style().button();
        return (float) Math.ceil(font.width(shown) + 2 * (b.padding().x() + b.border() + b.rounding()) + 4 * scale);
    }

    /** A button showing a texture (a course preview) at width x height. */
    public static boolean imageButton(int texture, float width, float height) {
        var b = ctx.style().button();
        float pad = b.padding().x() + b.border() + b.image_padding().x();
        place(width + 2 * pad, height + 2 * (b.padding().y() + b.border() + b.image_padding().y()));
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkImage image = nk_image_id(texture, NkImage.malloc(stack));
            return nk_button_image(ctx, image);
        }
    }

    public static boolean checkbox(String label, GuiBool value) {
        String shown = displayLabel(label);
        place(font.width(shown) + textH + 16 * scale + 4, frameH);
        boolean now = nk_check_label(ctx, shown, value.get());
        if (now == value.get()) return false;
        value.set(now);
        return true;
    }

    /** A round option; true when clicked. */
    public static boolean radioButton(String label, boolean active) {
        place(radioButtonWidth(label), frameH);
        String shown = displayLabel(label);
        return nk_option_label(ctx, shown, active) && !active;
    }

    /** The width a radio button with this label takes (to keep room for it before it shows). */
    public static float radioButtonWidth(String label) {
        return font.width(displayLabel(label)) + textH + 16 * scale + 4;
    }

    /** A row that can be selected (lists); true when clicked. */
    public static boolean selectable(String label, boolean selected) {
        String shown = displayLabel(label);
        placeFullRow(font.width(shown) + 16 * scale, textH + 4 * scale);
        return nk_select_label(ctx, shown, NK_TEXT_LEFT, selected) != selected;
    }

    public static void progressBar(float fraction, float width, float height) {
        progressBar(fraction, width, height, null);
    }

    /** A bar filled to {@code fraction}, with {@code overlay} (or the percentage) over it. */
    public static void progressBar(float fraction, float width, float height, String overlay) {
        float f = Math.max(0, Math.min(1, Float.isNaN(fraction) ? 0 : fraction));
        place(width > 0 ? width : takeItemWidth(), height > 0 ? height : frameH);
        nk_prog(ctx, Math.round(f * 1000), 1000, false);
        String text = overlay != null ? GuiText.fit(overlay, font, lastItem[2]) : Math.round(f * 100) + "%";
        float tw = font.width(text);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkRect r = NkRect.malloc(stack).set(lastItem[0] + (lastItem[2] - tw) / 2, lastItem[1] + (lastItem[3] - textH) / 2, tw + 2, textH);
            nk_draw_text(nk_window_get_canvas(ctx), r, text, font.userFont(), NkColor.calloc(stack), colour(stack, Theme.TEXT));
        }
    }

    // ---- Menus (GuiMenus) and tables (GuiTables) ----------------------------------------------

    /** A bar across the top of the screen for {@link #beginMenu}; pair with {@link #endMainMenuBar()}. */
    public static boolean beginMainMenuBar() {
        return GuiMenus.beginMainMenuBar();
    }

    public static void endMainMenuBar() {
        GuiMenus.endMainMenuBar();
    }

    /**
     * A menu: in the main menu bar a title that drops down, elsewhere a drop-down box with the label.
     * When it is open, add {@link #menuItem}s and call {@link #endMenu()}.
     */
    public static boolean beginMenu(String label) {
        return GuiMenus.beginMenu(label);
    }

    public static void endMenu() {
        GuiMenus.endMenu();
    }

    public static boolean menuItem(String label) {
        return GuiMenus.menuItem(label);
    }

    public static boolean menuItem(String label, String shortcut) {
        return GuiMenus.menuItem(label, shortcut);
    }

    /** An entry of the open menu: the shortcut on the right, a mark when selected, grey when not enabled. */
    public static boolean menuItem(String label, String shortcut, boolean selected, boolean enabled) {
        return GuiMenus.menuItem(label, shortcut, selected, enabled);
    }

    /** A table whose columns fit their widest cell (measured the frame before). */
    public static boolean beginTable(String id, int columns, int flags) {
        return GuiTables.beginTable(id, columns, flags);
    }

    public static void tableSetupColumn(String label) {
        GuiTables.tableSetupColumn(label);
    }

    public static void tableHeadersRow() {
        GuiTables.tableHeadersRow();
    }

    public static void tableNextRow() {
        GuiTables.tableNextRow();
    }

    public static void tableSetColumnIndex(int column) {
        GuiTables.tableSetColumnIndex(column);
    }

    public static void endTable() {
        GuiTables.endTable();
    }

    // ---- Fields (GuiFields) -----------------------------------------------------------------------

    public static boolean inputText(String label, GuiString value) {
        return GuiFields.inputText(label, value);
    }

    public static boolean inputDouble(String label, GuiDouble value) {
        return GuiFields.inputDouble(label, value, 0, 0, null);
    }

    public static boolean inputDouble(String label, GuiDouble value, double step, double stepFast) {
        return GuiFields.inputDouble(label, value, step, stepFast, null);
    }

    public static boolean inputDouble(String label, GuiDouble value, double step, double stepFast, String format) {
        return GuiFields.inputDouble(label, value, step, stepFast, format);
    }

    public static boolean inputInt(String label, GuiInt value) {
        return GuiFields.inputInt(label, value);
    }

    public static boolean sliderFloat(String label, float[] value, float min, float max) {
        return GuiFields.sliderFloat(label, value, min, max, "%.2f");
    }

    public static boolean sliderFloat(String label, float[] value, float min, float max, String format) {
        return GuiFields.sliderFloat(label, value, min, max, format);
    }

    public static boolean sliderInt(String label, int[] value, int min, int max) {
        return GuiFields.sliderInt(label, value, min, max);
    }

    public static boolean combo(String label, GuiInt selected, String[] items) {
        return GuiFields.combo(label, selected, items);
    }

    // ---- Drawing ----------------------------------------------------------------------------------

    /** Shapes behind every window, in window coordinates (this frame only). */
    public static GuiDrawList getBackgroundDrawList() {
        return background;
    }

    static NkColor colour(MemoryStack stack, int[] rgba) {
        return NkColor.malloc(stack).set((byte) rgba[0], (byte) rgba[1], (byte) rgba[2], (byte) rgba[3]);
    }

    /** Draws a label with the text colour to the right of the last widget, on its row. */
    static void trailingLabel(String label) {
        String shown = displayLabel(label);
        if (shown.isEmpty()) return;
        sameLine();
        boolean keep = lastDeactivatedAfterEdit;
        float[] item = lastItem.clone(); // the widget stays the last item (isItemHovered, tests)
        float w = font.width(shown) + 2;
        place(w, frameH);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            nk_label_colored(ctx, shown, NK_TEXT_LEFT, colour(stack, Theme.TEXT));
        }
        lastDeactivatedAfterEdit = keep;
        System.arraycopy(item, 0, lastItem, 0, 4);
    }
}
