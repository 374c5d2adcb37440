package minigolf.ui;

import org.lwjgl.nuklear.NkColor;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.nuklear.NkVec2;
import org.lwjgl.system.MemoryStack;

import static minigolf.ui.Gui.*;
import static org.lwjgl.nuklear.Nuklear.*;

/** {@link Gui}'s menus: the main menu bar, drop-down menus and their items. */
final class GuiMenus {
    private GuiMenus() {
    }

    /** A bar across the top of the screen for {@link #beginMenu}; pair with {@link #endMainMenuBar()}. */
    static boolean beginMainMenuBar() {
        float padY = 4 * scale;
        var style = ctx.style().window();
        setNextWindowPos(0, 0, GuiCond.Always);
        setNextWindowSize(layer.displayWidth(), frameH + 2 * padY + 2);
        float keptX = style.padding().x(), keptY = style.padding().y();
        style.padding().set(6 * scale, padY);
        begin("##mainmenubar", GuiWindowFlags.NoDecoration);
        style.padding().set(keptX, keptY);
        nk_menubar_begin(ctx);
        nk_layout_row_begin(ctx, NK_STATIC, frameH, MAX_COLUMNS);
        win.inMenuBar = true;
        return true;
    }

    static void endMainMenuBar() {
        nk_menubar_end(ctx);
        end();
    }

    /**
     * A menu: in the main menu bar a title that drops down, elsewhere a drop-down box with the label.
     * When it is open, add {@link #menuItem}s and call {@link #endMenu()}.
     */
    static boolean beginMenu(String label) {
        requireWindow();
        String shown = displayLabel(label), key = idPath(label);
        float[] size = menuSizes.getOrDefault(key, new float[]{200 * scale, 8});
        var pad = ctx.style().window().menu_padding();
        float spY = ctx.style().window().spacing().y();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkVec2 popup = NkVec2.malloc(stack).set(size[0] + 2 * pad.x(), size[1] * (frameH + spY) + 2 * pad.y() + spY);
            boolean open;
            if (win.inMenuBar) {
                nk_layout_row_push(ctx, font.width(shown) + 2 * ctx.style().menu_button().padding().x() + 8 * scale);
                open = nk_menu_begin_label(ctx, shown, NK_TEXT_CENTERED, popup);
            } else {
                float w = Math.max(takeItemWidth(), font.width(shown) + frameH + 24 * scale);
                place(w, frameH);
                open = nk_combo_begin_label(ctx, shown, popup.x(Math.max(popup.x(), w)));
            }
            if (!open) return false;
            recordPopup(stack);
            menus.push(new Menu(!win.inMenuBar, key));
            menuSizes.put(key, new float[]{0, 0});
            return true;
        }
    }

    private static void recordPopup(MemoryStack stack) {
        NkRect r = nk_window_get_bounds(ctx, NkRect.malloc(stack));
        building.rects.add(new float[]{r.x(), r.y(), r.w(), r.h()});
    }

    static void endMenu() {
        Menu m = menus.pop();
        if (m.combo()) nk_combo_end(ctx);
        else nk_menu_end(ctx);
    }

    static boolean menuItem(String label) {
        return menuItem(label, "", false, true);
    }

    static boolean menuItem(String label, String shortcut) {
        return menuItem(label, shortcut, false, true);
    }

    /** An entry of the open menu: the shortcut on the right, a mark when selected, grey when not enabled. */
    static boolean menuItem(String label, String shortcut, boolean selected, boolean enabled) {
        Menu m = menus.peek();
        if (m == null) throw new IllegalStateException("menuItem outside beginMenu");
        String shown = displayLabel(label), keys = shortcut == null ? "" : shortcut;
        float[] size = menuSizes.get(m.key());
        size[0] = Math.max(size[0], font.width(shown) + font.width(keys) + 48 * scale);
        size[1]++;
        nk_layout_row_dynamic(ctx, frameH, 1);
        recordItem();
        boolean hit;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            if (!enabled) {
                nk_label_colored(ctx, "  " + shown, NK_TEXT_LEFT, colour(stack, Theme.DISABLED_TEXT));
                hit = false;
            } else {
                hit = m.combo() ? nk_combo_item_label(ctx, shown, NK_TEXT_LEFT) : nk_menu_item_label(ctx, shown, NK_TEXT_LEFT);
            }
            var canvas = nk_window_get_canvas(ctx);
            float right = lastItem[0] + lastItem[2] - 6 * scale;
            if (!keys.isEmpty()) {
                float kw = font.width(keys);
                right -= kw;
                nk_draw_text(canvas, NkRect.malloc(stack).set(right, lastItem[1] + (lastItem[3] - textH) / 2, kw + 2, textH),
                        keys, font.userFont(), NkColor.calloc(stack), colour(stack, Theme.DISABLED_TEXT));
                right -= 10 * scale;
            }
            if (selected) {
                float s = textH * 0.5f;
                nk_fill_rect(canvas, NkRect.malloc(stack).set(right - s, lastItem[1] + (lastItem[3] - s) / 2, s, s), 2,
                        colour(stack, Theme.ACCENT));
            }
        }
        return hit;
    }

}
