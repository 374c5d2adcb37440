package minigolf.ui;

/** Text that a {@link Gui} text field edits in place, at most {@link #capacity()} UTF-8 bytes (as ImGui's ImString). */
public final class GuiString {
    private String value;
    private final int capacity;

    public GuiString(int capacity) {
        this("", capacity);
    }

    public GuiString(String value, int capacity) {
        this.capacity = Math.max(1, capacity);
        set(value);
    }

    public String get() {
        return value;
    }

    /** Sets the text, cut to the capacity (on a character boundary). */
    public void set(String text) {
        String t = text == null ? "" : text;
        while (t.getBytes(java.nio.charset.StandardCharsets.UTF_8).length > capacity) t = t.substring(0, t.length() - 1);
        value = t;
    }

    public int capacity() {
        return capacity;
    }
}
