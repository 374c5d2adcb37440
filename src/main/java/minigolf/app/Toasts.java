package minigolf.app;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleSupplier;
import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiWindowFlags;

/**
 * What the game says to the player over every screen: a one-line message at the bottom that fades
 * after a few seconds, and a notice at the top that stays until dismissed (a settings file that
 * was ignored).
 */
final class Toasts {
    /** How long a message stays, in seconds. */
    static final double SECONDS = 5;
    /** Messages said together are shown one a line, the latest this many (one line cut them short). */
    static final int MAX_LINES = 4;

    private final DoubleSupplier clock;
    private final List<String> lines = new ArrayList<>();
    private double until;
    private String notice;
    private float[] noticeRect;
    /** The notice's window, and the top of the screen it hangs from (interface units). */
    static final String NOTICE = "Notice##notice";
    static final float NOTICE_TOP = 16;

    Toasts(DoubleSupplier clock) {
        this.clock = clock;
    }

    void say(String text) {
        double now = clock.getAsDouble();
        // Said together (a holed stroke and the personal best it set): all stay, one a line.
        boolean together = !lines.isEmpty() && now <= until && now - (until - SECONDS) < 0.5;
        if (!together) lines.clear();
        lines.add(text);
        if (lines.size() > MAX_LINES) lines.remove(0);
        until = now + SECONDS;
    }

    /** The lines of the message shown now (the oldest first), empty when none is. */
    List<String> messageLines() {
        if (!lines.isEmpty() && clock.getAsDouble() > until) lines.clear();
        return List.copyOf(lines);
    }

    void setNotice(String text) {
        notice = text;
    }

    String notice() {
        return notice;
    }

    void dismissNotice() {
        notice = null;
    }

    /**
     * The lowest point of the notice at the top of the screen (interface units), where a panel at
     * the top goes below it; 0 without a notice, and in the notice's first frame (it measures itself
     * off screen then).
     */
    float noticeBottom() {
        float[] size = notice == null ? null : Gui.measuredSize(NOTICE);
        return size == null ? 0 : NOTICE_TOP + size[1];
    }

    /** Where the notice was drawn in the last frame ({x, y, w, h}), or null (tests). */
    float[] noticeRect() {
        return noticeRect;
    }

    /** Draws the notice and the message over whatever screen is shown. */
    void render(float w, float h) {
        noticeRect = null;
        if (notice != null) {
            Gui.setNextWindowPos(w * 0.5f, NOTICE_TOP, GuiCond.Always, 0.5f, 0f);
            Gui.begin(NOTICE, GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
            noticeRect = Gui.windowRect();
            for (String line : notice.split("\n")) Gui.text(line);
            if (Gui.button("Dismiss")) dismissNotice();
            Gui.end();
        }
        List<String> m = messageLines();
        if (!m.isEmpty()) {
            Gui.setNextWindowPos(w * 0.5f, h - 16, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##message", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize
                    | GuiWindowFlags.NoInputs | GuiWindowFlags.NoFocusOnAppearing);
            for (String line : m) Gui.text(line);
            Gui.end();
        }
    }
}
