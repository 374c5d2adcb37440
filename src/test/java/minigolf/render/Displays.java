package minigolf.render;

/** Whether this test run has a display, decided as {@link Window} decides it. */
public final class Displays {
    private Displays() {
    }

    /** On Linux an X server or a Wayland compositor; on Windows and macOS always. */
    public static boolean present() {
        if (!System.getProperty("os.name").toLowerCase(java.util.Locale.ROOT).contains("linux")) return true;
        return !isBlank(System.getenv("DISPLAY")) || !isBlank(System.getenv("WAYLAND_DISPLAY"));
    }

    private static boolean isBlank(String s) {
        return s == null || s.isBlank();
    }
}
