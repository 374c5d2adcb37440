package minigolf.ui;

/** Where the game's panels stand and how they look: centred menus, and final cards left of the course. */
public final class Panels {
    private Panels() {
    }

    /** A fixed panel that takes its content's size. */
    public static final int PANEL = GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize
            | GuiWindowFlags.AlwaysAutoResize;

    /** The final card's left edge, a share of the screen's width (the camera keeps the course right of it). */
    public static final float FINAL_CARD_LEFT = 0.03f;

    /** The next panel centred on the screen. */
    public static void centre(float w, float h) {
        Gui.setNextWindowPos(w * 0.5f, h * 0.5f, GuiCond.Always, 0.5f, 0.5f);
    }

    /** A final card stands at the left, so that the course the camera turns round shows beside it. */
    public static void leftOfCourse(float w, float h) {
        Gui.setNextWindowPos(w * FINAL_CARD_LEFT, h * 0.5f, GuiCond.Always, 0f, 0.5f);
    }

    /** A heading line in the theme's gold. */
    public static void heading(String text) {
        Gui.textColored(1f, 0.85f, 0.3f, 1f, text);
    }
}
