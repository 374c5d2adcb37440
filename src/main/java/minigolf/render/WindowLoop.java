package minigolf.render;

import java.nio.file.Path;
import java.util.function.BiConsumer;

import static org.lwjgl.glfw.GLFW.glfwGetTime;

/**
 * The one window loop of the game and the editor (lwjglbook's {@code Engine.run}): each pass polls
 * input, lets the app update, and draws and shows a frame unless the window is minimised; a
 * scripted run stops when the app says it is finished, saving that last frame as a PNG.
 */
public final class WindowLoop {
    private final Window window;
    private final WindowApp app;
    private Path screenshot;
    /** Called at the start of every pass, drawn or not, with the pass number and the window (tests resize with it). */
    private BiConsumer<Integer, Window> passHook = (pass, w) -> { };

    public WindowLoop(Window window, WindowApp app) {
        this.window = window;
        this.app = app;
    }

    /** Where the last frame of a finished run is saved, or null for none. */
    public WindowLoop screenshot(Path png) {
        this.screenshot = png;
        return this;
    }

    public WindowLoop onPass(BiConsumer<Integer, Window> hook) {
        this.passHook = hook;
        return this;
    }

    /** Runs until the window is closed or the app is finished; returns the frames drawn. */
    public int run() {
        double last = glfwGetTime(), start = last;
        int frames = 0, pass = 0;
        while (!window.shouldClose()) {
            passHook.accept(pass++, window);
            if (window.shouldClose()) break;
            double now = glfwGetTime(), elapsed = Math.min(0.25, now - last);
            last = now;
            window.pollEvents();
            app.update(elapsed, now);
            int fw = window.framebufferWidth(), fh = window.framebufferHeight();
            if (fw <= 0 || fh <= 0 || window.isIconified()) {
                sleep(50); // minimised: the app goes on, nothing is drawn
                continue;
            }
            app.render(fw, fh, (float) (now - start));
            frames++;
            if (app.finished(frames)) {
                if (screenshot != null) Png.saveBackBuffer(screenshot, fw, fh);
                window.swapBuffers();
                break;
            }
            window.swapBuffers();
            double wait = now + app.minFrameSeconds() - glfwGetTime();
            if (wait > 0.001) sleep((long) (wait * 1000));
        }
        return frames;
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
