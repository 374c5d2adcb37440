package minigolf.ui;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.nuklear.NkVec2;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.nuklear.Nuklear.*;
import static org.lwjgl.system.MemoryUtil.*;

/**
 * {@link Gui}'s edit fields, sliders and combos. A field shows its value while it is not edited; while
 * it is, the typed text is kept here (by window, ID stack and label) and a number field takes each
 * value that parses. Leaving the field (Enter, or a click elsewhere) ends the edit, and
 * {@link Gui#isItemDeactivatedAfterEdit()} says whether the text had changed.
 */
final class GuiFields {
    private static final class Field {
        boolean editing, edited;
        String text;
        long seen;
    }

    private static final Map<String, Field> fields = new HashMap<>();

    private GuiFields() {
    }

    static void clear() {
        fields.clear();
    }

    /** Fields not drawn in the frame are forgotten (their screen closed). */
    static void forgetUnseen(long frame) {
        fields.values().removeIf(f -> f.seen != frame);
    }

    /** Draws a text field of {@code width} showing {@code current}; returns the new text when it changed, else null. */
    private static String edit(String label, String current, int maxBytes, float width) {
        Field f = fields.computeIfAbsent(Gui.idPath(label), k -> new Field());
        f.seen = Gui.frameNumber();
        String shown = f.editing ? f.text : current;
        Gui.place(width, Gui.frameHeight());
        float[] r = Gui.lastItemRect();
        var mouse = Gui.ctx.input().mouse();
        var left = mouse.buttons(NK_BUTTON_LEFT);
        boolean clickedElsewhere = left.clicked() != 0 && left.down()
                && !(mouse.pos().x() >= r[0] && mouse.pos().x() < r[0] + r[2] && mouse.pos().y() >= r[1] && mouse.pos().y() < r[1] + r[3]);
        // A click on another window leaves this one without input; the edit must end all the same.
        if (f.editing && (clickedElsewhere || Gui.escape)) nk_edit_unfocus(Gui.ctx);
        String changed = null;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            byte[] bytes = shown.getBytes(StandardCharsets.UTF_8);
            int len = Math.min(bytes.length, maxBytes);
            ByteBuffer buffer = stack.malloc(maxBytes + 1);
            buffer.put(bytes, 0, len).put((byte) 0).clear(); // max counts the terminating zero
            IntBuffer length = stack.ints(len);
            int result = nk_edit_string(Gui.ctx, NK_EDIT_FIELD | NK_EDIT_SIG_ENTER, buffer, length, maxBytes + 1, null);
            String now = memUTF8(memAddress(buffer), length.get(0));
            boolean active = (result & NK_EDIT_ACTIVE) != 0, committed = (result & NK_EDIT_COMMITED) != 0;
            if (active || committed) {
                if (!f.editing) {
                    f.editing = true;
                    f.edited = false;
                    f.text = shown;
                }
                if (!now.equals(f.text)) {
                    f.edited = true;
                    f.text = now;
                    changed = now;
                }
                if (committed) {
                    nk_edit_unfocus(Gui.ctx);
                    finish(f);
                } else {
                    Gui.building().textFieldActive = true;
                }
            } else if (f.editing) {
                finish(f);
            }
        }
        return changed;
    }

    private static void finish(Field f) {
        boolean edited = f.edited;
        f.editing = false;
        f.edited = false;
        f.text = null;
        Gui.setDeactivatedAfterEdit(edited);
    }

    static boolean inputText(String label, GuiString value) {
        String t = edit(label, value.get(), value.capacity(), Gui.takeItemWidth());
        boolean deactivated = Gui.isItemDeactivatedAfterEdit();
        if (t != null) value.set(t);
        Gui.trailingLabel(label);
        Gui.setDeactivatedAfterEdit(deactivated);
        return t != null;
    }

    static boolean inputDouble(String label, GuiDouble value, double step, double stepFast, String format) {
        float w = Gui.takeItemWidth();
        boolean steps = step > 0;
        float small = Gui.frameHeight();
        float fieldW = steps ? Math.max(small * 2, w - 2 * (small + Gui.ctx.style().window().spacing().x())) : w;
        String t = edit(label, format(value.get(), format), 64, fieldW);
        boolean deactivated = Gui.isItemDeactivatedAfterEdit(), changed = false;
        if (t != null) {
            try {
                double v = Double.parseDouble(t.trim());
                if (Double.isFinite(v) && v != value.get()) {
                    value.set(v);
                    changed = true;
                }
            } catch (NumberFormatException ignored) {
                // not a number yet (typing "-" or "1e"): the value stays
            }
        }
        if (steps) {
            Gui.sameLine();
            if (Gui.stepButton(false)) {
                value.set(value.get() - step);
                changed = true;
            }
            Gui.sameLine();
            if (Gui.stepButton(true)) {
                value.set(value.get() + step);
                changed = true;
            }
        }
        Gui.trailingLabel(label);
        Gui.setDeactivatedAfterEdit(deactivated);
        return changed;
    }

    static boolean inputInt(String label, GuiInt value) {
        float w = Gui.takeItemWidth(), small = Gui.frameHeight();
        float fieldW = Math.max(small * 2, w - 2 * (small + Gui.ctx.style().window().spacing().x()));
        String t = edit(label, Integer.toString(value.get()), 32, fieldW);
        boolean deactivated = Gui.isItemDeactivatedAfterEdit(), changed = false;
        if (t != null) {
            try {
                int v = Integer.parseInt(t.trim());
                if (v != value.get()) {
                    value.set(v);
                    changed = true;
                }
            } catch (NumberFormatException ignored) {
                // not a number yet
            }
        }
        Gui.sameLine();
        if (Gui.stepButton(false)) {
            value.set(value.get() - 1);
            changed = true;
        }
        Gui.sameLine();
        if (Gui.stepButton(true)) {
            value.set(value.get() + 1);
            changed = true;
        }
        Gui.trailingLabel(label);
        Gui.setDeactivatedAfterEdit(deactivated);
        return changed;
    }

    /** The value as the format says, or with up to six decimals and no trailing zeros. */
    static String format(double v, String format) {
        if (format != null) return String.format(Locale.ROOT, format, v);
        String s = String.format(Locale.ROOT, "%.6f", v);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s + "0" : s;
    }

    static boolean sliderFloat(String label, float[] value, float min, float max, String format) {
        Gui.place(Gui.takeItemWidth(), Gui.frameHeight());
        boolean changed = false;
        Float pressed = trackPress(min, max);
        if (pressed != null && pressed != value[0]) {
            value[0] = pressed;
            changed = true;
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            FloatBuffer v = stack.floats(value[0]);
            if (nk_slider_float(Gui.ctx, min, v, max, (max - min) / 500f)) {
                value[0] = v.get(0);
                changed = true;
            }
        }
        valueAndLabel(String.format(Locale.ROOT, format, value[0]), label);
        return changed;
    }

    static boolean sliderInt(String label, int[] value, int min, int max) {
        Gui.place(Gui.takeItemWidth(), Gui.frameHeight());
        boolean changed = false;
        Float pressed = trackPress(min, max);
        if (pressed != null && Math.round(pressed) != value[0]) {
            value[0] = Math.round(pressed);
            changed = true;
        }
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer v = stack.ints(value[0]);
            if (nk_slider_int(Gui.ctx, min, v, max, 1)) {
                value[0] = v.get(0);
                changed = true;
            }
        }
        valueAndLabel(Integer.toString(value[0]), label);
        return changed;
    }

    /**
     * Where a press on the slider just placed, held down, puts its value: Nuklear's slider moves
     * only when its knob is dragged, so a click elsewhere on the track did nothing (the new-game
     * players slider "ignored clicks"). Null when the left button was not pressed on the slider.
     */
    private static Float trackPress(float min, float max) {
        float[] b = Gui.lastItemRect();
        var in = Gui.ctx.input();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkRect r = NkRect.malloc(stack).set(b[0], b[1], b[2], b[3]);
            if (b[2] <= 0 || !nk_input_has_mouse_click_down_in_rect(in, NK_BUTTON_LEFT, r, true)) return null;
        }
        float f = Math.max(0f, Math.min(1f, (in.mouse().pos().x() - b[0]) / b[2]));
        return min + f * (max - min);
    }

    private static void valueAndLabel(String value, String label) {
        String shown = Gui.displayLabel(label);
        Gui.trailingLabel(shown.isEmpty() ? value : value + "  " + shown);
    }

    static boolean combo(String label, GuiInt selected, String[] items) {
        float w = Gui.takeItemWidth(), h = Gui.frameHeight();
        Gui.place(w, h);
        int sel = items.length == 0 ? 0 : Math.max(0, Math.min(selected.get(), items.length - 1));
        items = java.util.Arrays.stream(items).map(Gui::fitted).toArray(String[]::new);
        float widest = w;
        for (String item : items) widest = Math.max(widest, Gui.textWidth(item) + 40 * Gui.font.height() / 16);
        var style = Gui.ctx.style().window();
        float popupH = Math.min(items.length, 10) * (h + style.spacing().y()) + 2 * style.combo_padding().y() + style.spacing().y();
        boolean changed = false;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            if (nk_combo_begin_label(Gui.ctx, items.length == 0 ? "" : items[sel], NkVec2.malloc(stack).set(widest, popupH))) {
                var bounds = nk_window_get_bounds(Gui.ctx, org.lwjgl.nuklear.NkRect.malloc(stack));
                Gui.building().rects.add(new float[]{bounds.x(), bounds.y(), bounds.w(), bounds.h()});
                for (int i = 0; i < items.length; i++) {
                    nk_layout_row_dynamic(Gui.ctx, h, 1);
                    if (nk_combo_item_label(Gui.ctx, items[i], NK_TEXT_LEFT)) {
                        changed = i != sel;
                        selected.set(i);
                    }
                }
                nk_combo_end(Gui.ctx);
            }
        }
        Gui.trailingLabel(label);
        return changed;
    }
}
