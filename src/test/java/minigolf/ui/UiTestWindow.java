package minigolf.ui;

import minigolf.render.Framebuffer;
import minigolf.render.Window;

import static org.lwjgl.opengl.GL11.*;

/**
 * What the UI tests draw into: a hidden window for the GL context, an offscreen target of the
 * window's size and a Nuklear layer, closed together. One frame clears the target to the given
 * colour, runs the widgets and renders them.
 */
final class UiTestWindow implements AutoCloseable {
    final Framebuffer target;
    final NuklearLayer layer;
    final Window window;
    private final int width, height;
    private final float red, green, blue;

    UiTestWindow(String title, int width, int height, float red, float green, float blue) {
        this.width = width;
        this.height = height;
        this.red = red;
        this.green = green;
        this.blue = blue;
        window = new Window(title, width, height, Window.Options.hidden());
        target = new Framebuffer(width, height, 0);
        layer = new NuklearLayer(0, 1f);
        layer.setDisplaySize(width, height, width, height);
    }

    void frame(Runnable ui) {
        target.bind();
        glViewport(0, 0, width, height);
        glClearColor(red, green, blue, 1f);
        glClear(GL_COLOR_BUFFER_BIT);
        layer.newFrame();
        ui.run();
        layer.render();
    }

    @Override
    public void close() {
        layer.close();
        target.close();
        window.close();
    }
}
