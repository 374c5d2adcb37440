package minigolf.ui;

/**
 * The camera's mouse scheme, the same in the game and the editor, and usable on a touchpad (whose
 * two-finger click is the right button and which often has no middle button):
 * <ul>
 * <li>rotate: right-drag, or Ctrl + left-drag;</li>
 * <li>pan: Shift + right-drag, middle-drag, or Ctrl + Shift + left-drag;</li>
 * <li>zoom: the wheel (a two-finger scroll).</li>
 * </ul>
 * A plain left-drag is the action: aiming in the game (which also turns the camera when the drag
 * starts away from the ball), the tool in the editor. Buttons and modifiers are GLFW's values.
 */
public enum CameraDrag {
    NONE, ROTATE, PAN;

    public static final int LEFT = 0, RIGHT = 1, MIDDLE = 2;
    public static final int SHIFT = 0x1, CONTROL = 0x2;

    /** What a drag that starts with {@code button} pressed and {@code mods} held does to the camera. */
    public static CameraDrag of(int button, int mods) {
        boolean shift = (mods & SHIFT) != 0, control = (mods & CONTROL) != 0;
        if (button == MIDDLE) return PAN;
        if (button == RIGHT) return shift ? PAN : ROTATE;
        if (button == LEFT && control) return shift ? PAN : ROTATE;
        return NONE;
    }

    /** The scheme in words, for the help screens and the README. */
    public static final String[][] HELP = {
        {"Turn the camera", "right-drag, or Ctrl + left-drag (touchpad)"},
        {"Move the camera", "Shift + right-drag, middle-drag, or Ctrl + Shift + left-drag"},
        {"Zoom", "mouse wheel or two-finger scroll"},
    };
}
