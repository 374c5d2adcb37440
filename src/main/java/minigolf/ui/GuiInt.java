package minigolf.ui;

/** An int that a {@link Gui} widget edits in place (as ImGui's ImInt). */
public final class GuiInt {
    private int value;

    public GuiInt() {
        this(0);
    }

    public GuiInt(int value) {
        this.value = value;
    }

    public int get() {
        return value;
    }

    public void set(int value) {
        this.value = value;
    }
}
