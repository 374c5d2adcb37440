package minigolf.app;

import minigolf.course.Course;
import minigolf.physics.World;
import minigolf.render.Framebuffer;
import minigolf.render.OrbitCamera;
import minigolf.render.Png;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import minigolf.render.Window;
import minigolf.terrain.Terrain;

import java.nio.ByteBuffer;
import java.nio.file.Path;

import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/**
 * Entry points to the game's window ({@link GameApp}) and to off-screen stills of a course.
 */
public final class GameWindow {
    private GameWindow() {
    }

    /** Opens the game (main menu) on the course and runs until it is closed. Blocks; call from the main thread. */
    public static void show(World world, Path coursePath) {
        new GameApp(world, GameApp.Options.interactive(coursePath)).run();
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
}
