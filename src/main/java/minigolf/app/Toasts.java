package minigolf.app;

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

    private final DoubleSupplier clock;
    private String message;
    private double until;
    private String notice;

    Toasts(DoubleSupplier clock) {
        this.clock = clock;
    }

    void say(String text) {
        double now = clock.getAsDouble();
        // Said together (a holed stroke and the personal best it set): both stay, side by side.
        message = message != null && now - (until - SECONDS) < 0.5 ? message + "   \u00b7   " + text : text;
        until = now + SECONDS;
    }

    /** The message shown now, or null. */
    String message() {
        if (message != null && clock.getAsDouble() > until) message = null;
        return message;
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

    /** Draws the notice and the message over whatever screen is shown. */
    void render(float w, float h) {
        if (notice != null) {
            Gui.setNextWindowPos(w * 0.5f, 16, GuiCond.Always, 0.5f, 0f);
            Gui.begin("Notice##notice", GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
            Gui.text(notice);
            if (Gui.button("Dismiss")) dismissNotice();
            Gui.end();
        }
        String m = message();
        if (m != null) {
            Gui.setNextWindowPos(w * 0.5f, h - 16, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##message", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize
                    | GuiWindowFlags.NoInputs | GuiWindowFlags.NoFocusOnAppearing);
            Gui.text(m);
            Gui.end();
        }
    }
}
