package minigolf.ui;

import java.util.ArrayList;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.system.MemoryStack;

import static minigolf.ui.Gui.*;
import static org.lwjgl.nuklear.Nuklear.*;

/** {@link Gui}'s tables: rows of fixed columns, each as wide as its widest cell the frame before. */
final class GuiTables {
    private GuiTables() {
    }

    /** A table whose columns fit their widest cell (measured the frame before). */
    static boolean beginTable(String id, int columns, int flags) {
        requireWindow();
        win.table = idPath(id);
        win.tableFlags = flags;
        win.tableRow = 0;
        float[] known = tableWidths.get(win.table);
        win.widths = known != null && known.length == columns ? known : filled(columns, 60 * scale);
        win.measured = new float[columns];
        win.headers = new ArrayList<>();
        win.rowOpen = false;
        return true;
    }

    private static float[] filled(int n, float v) {
        float[] a = new float[n];
        java.util.Arrays.fill(a, v);
        return a;
    }

    static void tableSetupColumn(String label) {
        win.headers.add(displayLabel(label));
    }

    static void tableHeadersRow() {
        tableNextRow();
        for (int i = 0; i < win.headers.size() && i < win.widths.length; i++) {
            tableSetColumnIndex(i);
            label(win.headers.get(i), Theme.ACCENT);
        }
        win.tableRow = 0; // bands count from the first row under the header
    }

    static void tableNextRow() {
        requireWindow();
        nk_layout_row_begin(ctx, NK_STATIC, textH + 2 * scale, MAX_COLUMNS);
        win.rowOpen = true;
        win.sameLine = false;
        win.nextColumn = 0;
        win.tableRow++;
        float rowW = 0;
        for (float w : win.widths) rowW += w;
        rowW += spacingX * (win.widths.length - 1);
        win.rowW = rowW;
        win.contentW = Math.max(win.contentW, rowW);
    }

    static void tableSetColumnIndex(int column) {
        requireWindow();
        if (column < win.nextColumn || column >= win.widths.length) return;
        while (win.nextColumn < column) {
            nk_layout_row_push(ctx, win.widths[win.nextColumn++]);
            nk_spacing(ctx, 1);
        }
        win.cellPending = true;
        win.cellWidth = win.widths[column];
        win.cellColumn = column;
        win.nextColumn = column + 1;
        if (column == 0 && (win.tableFlags & GuiTableFlags.RowBg) != 0 && win.tableRow % 2 == 0) {
            nk_layout_row_push(ctx, win.cellWidth);
            try (MemoryStack stack = MemoryStack.stackPush()) {
                NkRect r = nk_widget_bounds(ctx, NkRect.malloc(stack));
                nk_fill_rect(nk_window_get_canvas(ctx), r.set(r.x() - 3 * scale, r.y(), win.rowW + 6 * scale, r.h()), 3 * scale,
                        colour(stack, new int[]{255, 255, 255, 14}));
            }
        }
    }

    static void endTable() {
        requireWindow();
        float[] w = new float[win.measured.length];
        for (int i = 0; i < w.length; i++) w[i] = Math.max(8 * scale, win.measured[i] + 6 * scale);
        tableWidths.put(win.table, w);
        win.table = null;
        win.cellPending = false;
        win.rowOpen = false;
    }

}
