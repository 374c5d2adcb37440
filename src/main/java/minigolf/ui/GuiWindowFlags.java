package minigolf.ui;

/** Window flags for {@link Gui#begin(String, int)}, named as ImGui's. */
public final class GuiWindowFlags {
    public static final int None = 0;
    public static final int NoTitleBar = 1;
    public static final int NoResize = 1 << 1;
    public static final int NoMove = 1 << 2;
    public static final int NoScrollbar = 1 << 3;
    public static final int NoCollapse = 1 << 5;
    /** The window takes its content's size (the default for a window without a size). */
    public static final int AlwaysAutoResize = 1 << 6;
    /** Clicks go through to the game. */
    public static final int NoInputs = 1 << 9;
    public static final int NoFocusOnAppearing = 1 << 12;
    public static final int NoDecoration = NoTitleBar | NoResize | NoScrollbar | NoCollapse;

    private GuiWindowFlags() {
    }
}
