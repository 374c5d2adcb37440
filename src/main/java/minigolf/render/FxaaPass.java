package minigolf.render;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

/**
 * Anti-aliasing where there is no MSAA (software quality): the scene is drawn into an image of the
 * viewport's size ({@link #begin}), which {@link #resolve} then copies to the real target through
 * the FXAA filter ({@code fxaa.vert/frag}). Owns the image, the program and an empty vertex array;
 * {@link #close()} frees them.
 */
public final class FxaaPass implements AutoCloseable {
    private final RenderTarget image = new RenderTarget();
    private final ShaderProgram program;
    private final int emptyVao;
    private boolean closed;

    public FxaaPass() {
        program = ShaderProgram.load("fxaa");
        emptyVao = glGenVertexArrays();
    }

    /** Sizes the image to width x height and binds it: draw the scene, then {@link #resolve}. Returns its framebuffer. */
    public int begin(int width, int height) {
        image.ensureSize(width, height);
        image.bind();
        return image.framebuffer();
    }

    /** Draws the image, filtered, over the whole of {@code target} (a framebuffer, 0 the window's), and leaves it bound. */
    public void resolve(int target, int width, int height) {
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glViewport(0, 0, width, height);
        boolean depthTest = glIsEnabled(GL_DEPTH_TEST);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        program.use();
        image.bindColour(0);
        program.set("uImage", 0);
        program.set("uTexel", 1f / image.width(), 1f / image.height());
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);
        glBindTexture(GL_TEXTURE_2D, 0);
        if (depthTest) glEnable(GL_DEPTH_TEST);
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        image.close();
        program.close();
        glDeleteVertexArrays(emptyVao);
    }
}
