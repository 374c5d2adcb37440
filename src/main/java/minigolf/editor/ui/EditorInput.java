package minigolf.editor.ui;

import minigolf.editor.EditorKey;
import minigolf.editor.TerrainPicker;
import minigolf.editor.ToolController;
import minigolf.physics.World;
import minigolf.ui.CameraDrag;
import org.joml.Matrix4f;
import org.joml.Vector4f;

import static org.lwjgl.glfw.GLFW.*;

/**
 * The editor's keys and mouse: a left press uses the tool where the cursor meets the terrain (a
 * brush stroke dabbing as the cursor moves, an object placed, or an existing one dragged), the
 * game's camera scheme ({@link CameraDrag}) turns and moves the view, and the keyboard drives the
 * tool (WASD, ENTER, SHIFT, ...) and the shortcuts (CTRL+Z/Y/S, H, R, F11). Closing with unsaved
 * changes asks first.
 */
final class EditorInput {
    private final EditorApp app;
    private boolean rotating, panning, stroking, dragging;
    private int dragObject = -1;
    private double dragStartX, dragStartY, lastDabX, lastDabY;
    private double lastX, lastY;
    private boolean cursorSeen;

    EditorInput(EditorApp app) {
        this.app = app;
    }

    void install() {
        long h = app.window.handle();
        glfwSetKeyCallback(h, (win, key, scancode, action, mods) -> {
            if (action == GLFW_RELEASE || (app.uiLayer != null && app.uiLayer.wantsKeyboard())) return;
            boolean repeatable = key == GLFW_KEY_W || key == GLFW_KEY_A || key == GLFW_KEY_S || key == GLFW_KEY_D;
            if (action == GLFW_REPEAT && !repeatable) return;
            onKey(key, mods);
        });
        glfwSetWindowCloseCallback(h, win -> {
            if (app.editor.isDirty()) {
                glfwSetWindowShouldClose(win, false);
                app.dialog = EditorApp.Dialog.CONFIRM_CLOSE;
            }
        });
        glfwSetMouseButtonCallback(h, (win, button, action, mods) -> {
            boolean down = action == GLFW_PRESS;
            double[] x = new double[1], y = new double[1];
            glfwGetCursorPos(win, x, y);
            lastX = x[0];
            lastY = y[0];
            if (down && app.uiLayer != null && app.uiLayer.wantsMouse()) return;
            // The game's camera scheme (CameraDrag): right-drag or Ctrl + left-drag turns, Shift + right,
            // middle or Ctrl + Shift + left moves; a plain left press is the app.tool.
            CameraDrag drag = down ? CameraDrag.of(button, mods) : CameraDrag.NONE;
            if (down && drag != CameraDrag.NONE) {
                rotating = drag == CameraDrag.ROTATE;
                panning = drag == CameraDrag.PAN;
            } else if (!down && button != GLFW_MOUSE_BUTTON_LEFT) {
                rotating = false;
                panning = false;
            }
            if (button == GLFW_MOUSE_BUTTON_LEFT) {
                if (down && drag == CameraDrag.NONE) {
                    toolDown(x[0], y[0]);
                } else if (!down) {
                    if (rotating || panning) {
                        rotating = false;
                        panning = false;
                    }
                    toolUp(x[0], y[0]);
                }
            }
        });
        glfwSetCursorPosCallback(h, (win, x, y) -> {
            if (!cursorSeen) { // the first event only says where the pointer already was (e.g. under Xvfb)
                cursorSeen = true;
                lastX = x;
                lastY = y;
                return;
            }
            float dx = (float) (x - lastX), dy = (float) (y - lastY);
            lastX = x;
            lastY = y;
            if (rotating) {
                app.camera.rotate(-dx * 0.006f, dy * 0.006f);
            } else if (panning) {
                int[] ww = new int[1], wh = new int[1];
                glfwGetWindowSize(win, ww, wh);
                app.camera.pan(dx, dy, Math.max(1, wh[0]));
            } else if (app.uiLayer == null || !app.uiLayer.wantsMouse()) {
                toolMove(x, y);
            }
        });
        glfwSetScrollCallback(h, (win, xoff, yoff) -> {
            if (app.uiLayer == null || !app.uiLayer.wantsMouse()) app.camera.zoom((float) yoff);
        });
    }

    /** One key press (the GLFW callback and scripted input both end here). */
    void onKey(int key, int mods) {
        boolean ctrl = (mods & GLFW_MOD_CONTROL) != 0;
        if (ctrl) {
            switch (key) {
                case GLFW_KEY_Z -> app.say(app.tool.press(EditorKey.UNDO));
                case GLFW_KEY_Y -> app.say(app.tool.press(EditorKey.REDO));
                case GLFW_KEY_S -> app.save();
                default -> {
                }
            }
            return;
        }
        EditorKey k = switch (key) {
            case GLFW_KEY_W -> EditorKey.UP;
            case GLFW_KEY_A -> EditorKey.LEFT;
            case GLFW_KEY_S -> EditorKey.DOWN;
            case GLFW_KEY_D -> EditorKey.RIGHT;
            case GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT -> EditorKey.TOGGLE_TOOL;
            case GLFW_KEY_M -> EditorKey.WALL;
            case GLFW_KEY_B -> EditorKey.TREE;
            case GLFW_KEY_N -> EditorKey.NEXT_KIND;
            case GLFW_KEY_ENTER, GLFW_KEY_KP_ENTER -> EditorKey.PLACE;
            case GLFW_KEY_P -> EditorKey.DELETE;
            case GLFW_KEY_Q -> EditorKey.ROTATE_LEFT;
            case GLFW_KEY_E -> EditorKey.ROTATE_RIGHT;
            default -> null;
        };
        if (k != null) {
            app.say(app.tool.press(k));
            return;
        }
        switch (key) {
            case GLFW_KEY_H -> app.toggleHeightMap();
            case GLFW_KEY_R -> app.camera.reset();
            case GLFW_KEY_F11 -> app.window.toggleFullscreen();
            default -> {
            }
        }
    }


    private void toolDown(double cx, double cy) {
        double[] p = pick(cx, cy);
        if (p == null) return;
        app.tool.moveTo(p[0], p[1]);
        if (app.tool.isBrushAction()) {
            app.editor.beginStroke(app.tool.brush(), p[0], p[1], app.tool.radius, app.tool.strength);
            stroking = true;
            lastDabX = p[0];
            lastDabY = p[1];
            return;
        }
        if (app.tool.mode() == ToolController.Mode.OBJECT) {
            int k = app.editor.obstacleNear(p[0], p[1], ToolController.PICK_DISTANCE);
            if (k >= 0) { // drag an existing object
                app.selected = k;
                dragObject = k;
                dragging = true;
                dragStartX = p[0];
                dragStartY = p[1];
                return;
            }
        }
        app.say(app.tool.applyAt(p[0], p[1]));
    }

    private void toolMove(double cx, double cy) {
        double[] p = pick(cx, cy);
        if (p == null) return;
        app.tool.moveTo(p[0], p[1]);
        if (stroking && Math.hypot(p[0] - lastDabX, p[1] - lastDabY) >= 0.25 * app.tool.radius) {
            app.editor.dab(p[0], p[1]);
            lastDabX = p[0];
            lastDabY = p[1];
        }
    }

    private void toolUp(double cx, double cy) {
        if (stroking) {
            stroking = false;
            app.editor.endStroke();
        }
        if (dragging) {
            dragging = false;
            double[] p = pick(cx, cy);
            if (p != null && Math.hypot(p[0] - dragStartX, p[1] - dragStartY) > 1e-3) {
                app.editor.moveObstacle(dragObject, p[0] - dragStartX, p[1] - dragStartY);
            }
            dragObject = -1;
        }
    }

    /** Cursor (window coordinates) to the terrain point under it, or null. */
    private double[] pick(double cx, double cy) {
        if (app.camera == null) return null;
        int[] ww = new int[1], wh = new int[1];
        glfwGetWindowSize(app.window.handle(), ww, wh);
        int fw = app.window.framebufferWidth(), fh = app.window.framebufferHeight();
        double x = cx * fw / Math.max(1, ww[0]), y = cy * fh / Math.max(1, wh[0]);
        float nx = (float) (2 * x / fw - 1), ny = (float) (1 - 2 * y / fh);
        Matrix4f inv = app.camera.viewProjection((float) fw / fh, new Matrix4f()).invert();
        Vector4f near = new Vector4f(nx, ny, -1, 1).mul(inv), far = new Vector4f(nx, ny, 1, 1).mul(inv);
        near.div(near.w);
        far.div(far.w);
        World w = app.editor.world();
        return TerrainPicker.pick(w.terrain(), w.bounds(), near.x, near.y, near.z, far.x - near.x, far.y - near.y,
                far.z - near.z, 0.5 * app.editor.course().spacing());
    }
}
