package minigolf.app;

import minigolf.ui.CameraDrag;

import static org.lwjgl.glfw.GLFW.GLFW_MOUSE_BUTTON_LEFT;

/**
 * The camera under the mouse, on every screen that shows the course: the scheme shared with the
 * editor ({@link CameraDrag}: right-drag or Ctrl + left-drag turns, Shift + right-drag, middle-drag
 * or Ctrl + Shift + left-drag moves), a plain left-drag turns too, the wheel zooms. A screen that
 * uses a press itself (an aim from the ball) takes it first.
 */
final class CameraControls {
    private final GameApp app;
    private boolean rotating, panning;
    private double lastX, lastY;

    CameraControls(GameApp app) {
        this.app = app;
    }

    /** A press or release the screen did not use ({@code used} false), or one it did (only the cursor is noted). */
    void mouseButton(int button, boolean down, int mods, double x, double y, boolean used) {
        lastX = x;
        lastY = y;
        if (used) return;
        CameraDrag drag = down ? CameraDrag.of(button, mods) : CameraDrag.NONE;
        if (drag != CameraDrag.NONE || !down) {
            rotating = drag == CameraDrag.ROTATE;
            panning = drag == CameraDrag.PAN;
        }
        if (button == GLFW_MOUSE_BUTTON_LEFT && drag == CameraDrag.NONE && down) rotating = true;
        app.scene().playerMoves(rotating || panning);
    }

    /** The cursor moved; the camera turns or moves with it unless the screen used the move. */
    void cursorMoved(double x, double y, boolean used, int windowHeight) {
        float dx = (float) (x - lastX), dy = (float) (y - lastY);
        lastX = x;
        lastY = y;
        if (used || app.scene().camera() == null) return;
        if (rotating) {
            float k = (float) (0.006 * app.settings().mouseSpeed());
            app.scene().camera().rotate(-dx * k, dy * k);
        } else if (panning) {
            app.scene().camera().pan(dx, dy, Math.max(1, windowHeight));
        }
    }

    void zoom(double dy) {
        if (app.scene().camera() != null) app.scene().camera().zoom((float) dy);
    }
}
