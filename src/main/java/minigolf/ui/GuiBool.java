package minigolf.ui;

/** A boolean that a {@link Gui} widget edits in place (as ImGui's ImBoolean). */
public final class GuiBool {
    private boolean value;

    public GuiBool() {
        this(false);
    }

    public GuiBool(boolean value) {
        this.value = value;
    }

    public boolean get() {
        return value;
    }

    public void set(boolean value) {
        this.value = value;
    }
}
