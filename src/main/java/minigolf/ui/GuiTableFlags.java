package minigolf.ui;

/** Table flags for {@link Gui#beginTable}, named as ImGui's. Columns always fit their widest cell. */
public final class GuiTableFlags {
    public static final int None = 0;
    /** A line under the header row. */
    public static final int Borders = 1;
    /** Every other row on a lighter band. */
    public static final int RowBg = 1 << 1;
    public static final int SizingFixedFit = 1 << 2;

    private GuiTableFlags() {
    }
}
