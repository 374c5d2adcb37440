package minigolf.ui;

/** A double that a {@link Gui} widget edits in place (as ImGui's ImDouble). */
public final class GuiDouble {
    private double value;

    public GuiDouble() {
        this(0);
    }

    public GuiDouble(double value) {
        this.value = value;
    }

    public double get() {
        return value;
    }

    public void set(double value) {
        this.value = value;
    }
}
