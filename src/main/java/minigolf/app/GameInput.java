package minigolf.app;

import minigolf.game.AimModel;
import minigolf.game.Loft;
import minigolf.game.PlayerState;
import minigolf.ui.CameraDrag;
import minigolf.ui.Screen;
import org.joml.Vector3f;

import static org.lwjgl.glfw.GLFW.*;

/**
 * The game's keys and mouse: a left-drag from the ball aims (the wheel or Up/Down sets the loft),
 * the camera scheme shared with the editor ({@link CameraDrag}) turns and moves the view, and the
 * shortcuts (ESC, F1, F11, R, H, SPACE). Holds the aim's state; the game reads it to draw the aim.
 */
final class GameInput {
    /** How near the ball (pixels at 900 px high) a press must be to start an aim. */
    private static final double AIM_PICK_PIXELS = 48;

    private final GameApp app;
    boolean rotating, panning, aiming;
    private double lastX, lastY;
    /** The aimed velocity (vx, vy) while aiming, or null. */
    double[] aimVelocity;
    /** The loft for the next stroke (Loft: 0 = putt, up to 60 degrees), set with the wheel while aiming or Up/Down. */
    int loft;

    GameInput(GameApp app) {
        this.app = app;
    }

    /** Installed before the interface layer, whose GLFW callbacks chain to these. */
    void install() {
        long h = app.window.handle();
        glfwSetKeyCallback(h, (win, key, scancode, action, mods) -> {
            if (action != GLFW_PRESS || (app.uiLayer != null && app.uiLayer.wantsKeyboard())) return;
            switch (key) {
                case GLFW_KEY_ESCAPE -> escape();
                case GLFW_KEY_F1 -> {
                    if (app.screens.screen() == Screen.HELP) app.screens.closeHelp();
                    else app.screens.openHelp();
                }
                case GLFW_KEY_F11 -> app.window.toggleFullscreen();
                case GLFW_KEY_R -> app.camera.reset();
                case GLFW_KEY_UP, GLFW_KEY_DOWN -> loft = Loft.step(loft, key == GLFW_KEY_UP ? 1 : -1);
                case GLFW_KEY_H -> app.renderer.terrainPass().setColorMode(app.renderer.terrainPass().colorMode().next());
                case GLFW_KEY_SPACE -> {
                    if (app.animator != null) { // skip the animation: the same stroke, run to its end
                        app.animator.advance(1e9, 1);
                        while (!app.animator.isFinished()) app.animator.advance(1e9, 1);
                    }
                }
                default -> {
                }
            }
        });
        glfwSetMouseButtonCallback(h, (win, button, action, mods) -> {
            boolean down = action == GLFW_PRESS;
            double[] x = new double[1], y = new double[1];
            glfwGetCursorPos(win, x, y);
            if (down && app.uiLayer != null && app.uiLayer.wantsMouse()) return;
            // The camera's scheme is the editor's (CameraDrag); a plain left-drag aims, or turns away from the ball.
            CameraDrag drag = down && !aiming ? CameraDrag.of(button, mods) : CameraDrag.NONE;
            if (drag != CameraDrag.NONE || !down) {
                rotating = drag == CameraDrag.ROTATE;
                panning = drag == CameraDrag.PAN;
                if (down) app.turnToHole = false; // the player's own view wins
            }
            if (button == GLFW_MOUSE_BUTTON_LEFT && drag == CameraDrag.NONE) {
                if (down && app.canAim() && nearBall(x[0], y[0])) {
                    aiming = true;
                    aimVelocity = null;
                } else if (!down && aiming) {
                    aiming = false;
                    double[] v = aimVelocity;
                    aimVelocity = null;
                    if (v != null && Math.hypot(v[0], v[1]) > 0.02) {
                        double[] shot = Loft.velocity(v[0], v[1], loft, app.world.physics().maxSpeed());
                        app.hit(shot[0], shot[1], shot[2]);
                    }
                } else if (down) {
                    rotating = true;
                    app.turnToHole = false;
                }
            }
            if (button == GLFW_MOUSE_BUTTON_RIGHT && down && aiming) {
                aiming = false; // right click cancels the aim
                aimVelocity = null;
            }
            lastX = x[0];
            lastY = y[0];
        });
        glfwSetCursorPosCallback(h, (win, x, y) -> {
            float dx = (float) (x - lastX), dy = (float) (y - lastY);
            lastX = x;
            lastY = y;
            if (aiming) {
                aimVelocity = aimFromCursor(x, y);
            } else if (rotating) {
                float k = (float) (0.006 * app.settings.mouseSpeed());
                app.camera.rotate(-dx * k, dy * k);
            } else if (panning) {
                int[] ww = new int[1], wh = new int[1];
                glfwGetWindowSize(win, ww, wh);
                app.camera.pan(dx, dy, Math.max(1, wh[0]));
            }
        });
        glfwSetScrollCallback(h, (win, xoff, yoff) -> {
            if (app.uiLayer != null && app.uiLayer.wantsMouse()) return;
            if (aiming) loft = Loft.step(loft, (int) Math.signum(yoff)); // while aiming the wheel lofts the shot
            else app.camera.zoom((float) yoff);
        });
    }

    private void escape() {
        switch (app.screens.screen()) {
            case PLAYING -> app.screens.show(Screen.PAUSED);
            case PAUSED -> app.screens.show(Screen.PLAYING);
            case TEST_BOT -> app.toMainMenu();
            case COURSES, NEW_GAME, SETTINGS, SCORECARD -> app.screens.show(app.game != null && !app.game.isOver()
                    && app.screens.screen() == Screen.SETTINGS ? Screen.PAUSED : Screen.MAIN_MENU);
            case HELP -> app.screens.closeHelp();
            case REPLAY -> app.stopReplay();
            case ROUND_CARD -> {
                if (app.round != null && app.round.isOver()) app.toMainMenu();
            }
            case MAIN_MENU -> {
            }
        }
    }

    /** Cursor (window coordinates) to framebuffer pixels. */
    private double[] toFramebuffer(double x, double y) {
        int[] ww = new int[1], wh = new int[1];
        glfwGetWindowSize(app.window.handle(), ww, wh);
        double sx = (double) app.window.framebufferWidth() / Math.max(1, ww[0]);
        double sy = (double) app.window.framebufferHeight() / Math.max(1, wh[0]);
        return new double[]{x * sx, y * sy};
    }

    private boolean nearBall(double x, double y) {
        PlayerState s = app.game.player(app.game.currentPlayer());
        int fw = app.window.framebufferWidth(), fh = app.window.framebufferHeight();
        float[] p = app.camera.project(new Vector3f((float) s.x(), (float) s.y(), (float) app.world.terrain().height(s.x(), s.y())), fw, fh);
        double[] c = toFramebuffer(x, y);
        return p != null && Math.hypot(p[0] - c[0], p[1] - c[1]) <= AIM_PICK_PIXELS * Math.max(1, fh / 900.0);
    }

    /** Where the cursor ray meets the horizontal plane through the ball, turned into a shot. */
    private double[] aimFromCursor(double x, double y) {
        PlayerState s = app.game.player(app.game.currentPlayer());
        double[] c = toFramebuffer(x, y), p = minigolf.render.CursorRay.onPlane(app.camera, app.window.framebufferWidth(),
                app.window.framebufferHeight(), c[0], c[1], app.world.terrain().height(s.x(), s.y()));
        if (p == null) return aimVelocity;
        return AimModel.velocityForPull(s.x(), s.y(), p[0], p[1], app.world.physics().maxSpeed(), AimModel.DEFAULT_FULL_PULL);
    }
}
