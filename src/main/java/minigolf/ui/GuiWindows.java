package minigolf.ui;

import org.lwjgl.nuklear.NkPanel;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.system.MemoryStack;

import static minigolf.ui.Gui.*;
import static org.lwjgl.nuklear.Nuklear.*;

/**
 * {@link Gui}'s windows: placed every frame where the screens say, with a pivot, and sized to their
 * content as measured at the end of the frame before (a first frame measures off screen). A window
 * taller than the screen, or than its size constraint, scrolls.
 */
final class GuiWindows {
    private GuiWindows() {
    }

    static boolean begin(String name, int flags) {
        if (win != null) throw new IllegalStateException("window '" + name + "' inside '" + win.id + "'");
        String title = displayLabel(name), id = windowId(name);
        WindowMemory m = windows.computeIfAbsent(id, k -> new WindowMemory());
        boolean titled = (flags & GuiWindowFlags.NoTitleBar) == 0 && !title.isEmpty();
        float dw = layer.displayWidth(), dh = layer.displayHeight(), margin = 4 * scale;
        float w = nextSize != null && nextSize[0] > 0 ? nextSize[0] : m.measured ? m.needW : 300 * scale;
        float h = nextSize != null && nextSize[1] > 0 ? nextSize[1] : m.measured ? m.needH : 200 * scale;
        float[] pos = nextPos != null ? nextPos : new float[]{40 * scale, 40 * scale, 0, 0};
        float maxH = dh - 2 * margin;
        if (nextConstraints != null) {
            w = Math.max(nextConstraints[0], Math.min(w, nextConstraints[2]));
            h = Math.max(nextConstraints[1], h);
            maxH = Math.min(maxH, nextConstraints[3]);
        }
        nextPos = null;
        nextSize = null;
        nextConstraints = null;
        // Too tall for the screen: as tall as fits, with a scrollbar.
        float top = Math.max(0, pos[1] - h * pos[3]);
        boolean scroll = h > maxH || (pos[3] == 0 && top + h > dh - margin);
        if (scroll) h = Math.min(maxH, pos[3] == 0 ? Math.max(frameH * 3, dh - top - margin) : maxH);
        if (scroll) w += ctx.style().window().scrollbar_size().x();
        float x = Math.round(pos[0] - w * pos[2]), y = Math.round(pos[1] - h * pos[3]);
        x = Math.max(0, Math.min(x, dw - w));
        y = Math.max(0, Math.min(y, dh - h));
        boolean hidden = !m.measured; // its first frame only measures it: off screen, so it does not flash at a guessed size
        if (hidden) {
            x = -4000;
            y = -4000;
        }
        int nk = NK_WINDOW_BORDER | (titled ? NK_WINDOW_TITLE : 0) | (scroll ? 0 : NK_WINDOW_NO_SCROLLBAR)
                | ((flags & GuiWindowFlags.NoInputs) != 0 ? NK_WINDOW_NO_INPUT : 0);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkRect r = NkRect.malloc(stack).set(x, y, w, h);
            nk_window_set_bounds(ctx, id, r);
            nk_begin_titled(ctx, id, title.isEmpty() ? " " : title, r, nk);
        }
        if ((flags & GuiWindowFlags.NoInputs) == 0 && !hidden) building.rects.add(new float[]{x, y, w, h});
        win = new Win();
        win.id = id;
        win.memory = m;
        win.x = x;
        win.y = y;
        win.w = w;
        win.h = h;
        win.contentW = titled ? font.width(title) + 2 * ctx.style().window().header().padding().x() : 0;
        return true;
    }

    static void end() {
        requireWindow();
        try (MemoryStack stack = MemoryStack.stackPush()) {
            NkPanel p = nk_window_get_panel(ctx);
            float bottom = p.at_y() + p.row().height();
            float padY = ctx.style().window().padding().y(), spY = ctx.style().window().spacing().y();
            win.memory.needH = (float) Math.ceil(bottom - win.y + Math.max(0, padY - spY) + p.footer_height() + p.border());
            float chromeW = win.w - p.bounds().w();
            win.memory.needW = (float) Math.ceil(win.contentW + chromeW);
            win.memory.measured = true;
        }
        nk_end(ctx);
        win = null;
        ids.clear();
    }
}
