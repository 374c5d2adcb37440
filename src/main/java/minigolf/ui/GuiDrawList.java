package minigolf.ui;

import java.util.ArrayList;
import java.util.List;
import org.lwjgl.nuklear.NkColor;
import org.lwjgl.nuklear.NkCommandBuffer;
import org.lwjgl.nuklear.NkContext;
import org.lwjgl.nuklear.NkRect;
import org.lwjgl.nuklear.NkUserFont;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.nuklear.Nuklear.*;

/**
 * Lines, circles and labels over the course, behind every window (as ImGui's background draw list):
 * the bot's route, the editor's markers. Colours are ABGR ints (0xAABBGGRR) as in ImGui. The shapes
 * are kept during the frame and drawn by {@link Gui} at its end into a transparent full-screen window
 * that takes no input.
 */
public final class GuiDrawList {
    private record Op(int kind, float a, float b, float c, float d, int colour, float thickness, String text, int plate) {
    }

    private static final int LINE = 0, CIRCLE = 1, DISC = 2, TEXT = 3, LABEL = 4;
    private final List<Op> ops = new ArrayList<>();

    public void addLine(float x1, float y1, float x2, float y2, int abgr, float thickness) {
        ops.add(new Op(LINE, x1, y1, x2, y2, abgr, thickness, null, 0));
    }

    public void addCircle(float x, float y, float radius, int abgr, int segments, float thickness) {
        ops.add(new Op(CIRCLE, x, y, radius, 0, abgr, thickness, null, 0));
    }

    public void addCircleFilled(float x, float y, float radius, int abgr) {
        ops.add(new Op(DISC, x, y, radius, 0, abgr, 0, null, 0));
    }

    public void addText(float x, float y, int abgr, String text) {
        ops.add(new Op(TEXT, x, y, 0, 0, abgr, 0, text, 0));
    }

    /**
     * A label centred on x with its bottom at y, on a rounded plate of {@code plateAbgr} (a name tag
     * over a ball).
     */
    public void addLabel(float x, float y, int textAbgr, int plateAbgr, String text) {
        ops.add(new Op(LABEL, x, y, 0, 0, textAbgr, 0, text, plateAbgr));
    }

    /** A label's text as drawn on a screen {@code width} wide: cut to half the screen ({@link Gui#labelPlate} measures the same). */
    static String labelText(String text, FontAtlas font, float width) {
        return GuiText.fit(text, font, Math.max(font.height(), width / 2));
    }

    /** The room a label's plate leaves round its text, for text {@code textHeight} high. */
    static float labelPad(float textHeight) {
        return 0.25f * textHeight;
    }

    int size() {
        return ops.size();
    }

    /** Draws the frame's shapes into the background window and forgets them. */
    void flush(NkContext ctx, float width, float height, FontAtlas font) {
        if (ops.isEmpty()) return;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            var style = ctx.style().window();
            NkColor keptBackground = NkColor.malloc(stack).set(style.fixed_background().data().color());
            float padX = style.padding().x(), padY = style.padding().y();
            style.fixed_background().data().color().set((byte) 0, (byte) 0, (byte) 0, (byte) 0);
            style.padding().set(0, 0);
            NkRect all = NkRect.malloc(stack).set(0, 0, width, height);
            nk_begin(ctx, "##background", all, NK_WINDOW_BACKGROUND | NK_WINDOW_NO_INPUT | NK_WINDOW_NO_SCROLLBAR);
            style.fixed_background().data().color().set(keptBackground);
            style.padding().set(padX, padY);
            NkCommandBuffer canvas = nk_window_get_canvas(ctx);
            NkUserFont userFont = font.userFont();
            NkColor colour = NkColor.malloc(stack), none = NkColor.calloc(stack);
            NkRect r = NkRect.malloc(stack);
            for (Op op : ops) {
                int c = op.colour;
                colour.set((byte) c, (byte) (c >> 8), (byte) (c >> 16), (byte) (c >>> 24));
                switch (op.kind) {
                    case LINE -> nk_stroke_line(canvas, op.a, op.b, op.c, op.d, op.thickness, colour);
                    case CIRCLE -> nk_stroke_circle(canvas, r.set(op.a - op.c, op.b - op.c, 2 * op.c, 2 * op.c), op.thickness, colour);
                    case DISC -> nk_fill_circle(canvas, r.set(op.a - op.c, op.b - op.c, 2 * op.c, 2 * op.c), colour);
                    case LABEL -> {
                        String text = labelText(op.text, font, width);
                        float w = font.width(text) + 2, h = font.height(), pad = labelPad(h);
                        int p = op.plate;
                        NkColor plate = NkColor.malloc(stack).set((byte) p, (byte) (p >> 8), (byte) (p >> 16), (byte) (p >>> 24));
                        float left = op.a - w / 2, top = op.b - h - pad;
                        nk_fill_rect(canvas, r.set(left - pad, top - pad, w + 2 * pad, h + 2 * pad), 0.5f * h, plate);
                        nk_draw_text(canvas, r.set(left, top, w, h), text, userFont, none, colour);
                    }
                    default -> {
                        String text = GuiText.fit(op.text, font, Math.max(font.height(), width - op.a));
                        nk_draw_text(canvas, r.set(op.a, op.b, font.width(text) + 2, font.height()), text, userFont, none, colour);
                    }
                }
            }
            nk_end(ctx);
        }
        ops.clear();
    }

    void clear() {
        ops.clear();
    }
}
