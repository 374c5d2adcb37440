package minigolf.app;

import minigolf.course.Course;
import minigolf.render.Framebuffer;
import minigolf.render.OrbitCamera;
import minigolf.render.Png;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import minigolf.render.Window;
import minigolf.terrain.Terrain;

import java.nio.ByteBuffer;
import java.nio.file.Path;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/**
 * The game's window: a course, its ball and hole, an orbit camera. Left-drag rotates, right-drag
 * pans, the wheel zooms, R resets the view, H toggles the height-map colouring, ESC closes.
 */
public final class GameWindow {
    private GameWindow() {
    }

    /** Opens a window on the course and runs until it is closed. Blocks; call from the main thread. */
    public static void show(Course course, Terrain terrain) {
        try (Window window = new Window("Minigolf - " + course.name(), 1280, 800, Window.Options.visibleDefaults());
             SceneRenderer renderer = new SceneRenderer(course, terrain, TerrainMesh.ColorMode.GREEN)) {
            OrbitCamera camera = OrbitCamera.behindBall(course, terrain,
                    (float) window.framebufferWidth() / Math.max(1, window.framebufferHeight()));
            Controls controls = new Controls(window, camera, renderer);
            controls.install();
            double start = glfwGetTime();
            while (!window.shouldClose()) {
                int w = window.framebufferWidth(), h = window.framebufferHeight();
                if (w > 0 && h > 0) { // 0 x 0 while minimised
                    renderer.render(camera, w, h, (float) (glfwGetTime() - start));
                }
                window.swapBuffers();
                window.pollEvents();
            }
        }
    }

    /** Renders the opening view of the course into a width x height PNG, off-screen. */
    public static void screenshot(Course course, Terrain terrain, int width, int height, Path png) {
        screenshot(course, terrain, null, TerrainMesh.ColorMode.GREEN, width, height, png);
    }

    /**
     * Renders one frame into an off-screen framebuffer of a hidden window and writes it as PNG.
     * {@code camera} null means the opening view ({@link OrbitCamera#behindBall}).
     */
    public static void screenshot(Course course, Terrain terrain, OrbitCamera camera, TerrainMesh.ColorMode mode,
                                  int width, int height, Path png) {
        try (Window window = new Window("Minigolf screenshot", 64, 64, Window.Options.hidden());
             SceneRenderer renderer = new SceneRenderer(course, terrain, mode);
             Framebuffer target = new Framebuffer(width, height, 4)) {
            OrbitCamera cam = camera != null ? camera : OrbitCamera.behindBall(course, terrain, (float) width / height);
            target.bind();
            renderer.render(cam, width, height, 0f);
            target.resolve();
            ByteBuffer pixels = memAlloc(width * height * 4);
            try {
                target.readPixels(pixels);
                Png.writeBottomUp(png, width, height, pixels);
            } finally {
                memFree(pixels);
            }
        }
    }

    /** Mouse and keyboard: the GLFW callbacks are freed with the window. */
    private static final class Controls {
        private final Window window;
        private final OrbitCamera camera;
        private final SceneRenderer renderer;
        private boolean rotating;
        private boolean panning;
        private double lastX;
        private double lastY;

        Controls(Window window, OrbitCamera camera, SceneRenderer renderer) {
            this.window = window;
            this.camera = camera;
            this.renderer = renderer;
        }

        void install() {
            long h = window.handle();
            glfwSetKeyCallback(h, (win, key, scancode, action, mods) -> {
                if (action != GLFW_PRESS) return;
                switch (key) {
                    case GLFW_KEY_ESCAPE -> window.requestClose();
                    case GLFW_KEY_R -> camera.reset();
                    case GLFW_KEY_H -> renderer.terrainPass().setColorMode(renderer.terrainPass().colorMode().next());
                    default -> {
                    }
                }
            });
            glfwSetMouseButtonCallback(h, (win, button, action, mods) -> {
                boolean down = action == GLFW_PRESS;
                if (button == GLFW_MOUSE_BUTTON_LEFT) rotating = down;
                if (button == GLFW_MOUSE_BUTTON_RIGHT) panning = down;
                if (down) {
                    double[] x = new double[1], y = new double[1];
                    glfwGetCursorPos(win, x, y);
                    lastX = x[0];
                    lastY = y[0];
                }
            });
            glfwSetCursorPosCallback(h, (win, x, y) -> {
                float dx = (float) (x - lastX), dy = (float) (y - lastY);
                lastX = x;
                lastY = y;
                if (rotating) {
                    camera.rotate(-dx * 0.006f, dy * 0.006f);
                } else if (panning) {
                    // Cursor coordinates are screen units; scale to the window height in the same units.
                    int[] ww = new int[1], wh = new int[1];
                    glfwGetWindowSize(win, ww, wh);
                    camera.pan(dx, dy, Math.max(1, wh[0]));
                }
            });
            glfwSetScrollCallback(h, (win, xoff, yoff) -> camera.zoom((float) yoff));
        }
    }
}
