package minigolf.ui;

/** Conditions for {@link Gui#setNextWindowPos}; windows are placed every frame, so all mean Always. */
public final class GuiCond {
    public static final int None = 0;
    public static final int Always = 1;

    private GuiCond() {
    }
}
