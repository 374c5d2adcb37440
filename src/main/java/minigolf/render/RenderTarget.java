package minigolf.render;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL13.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13.glActiveTexture;
import static org.lwjgl.opengl.GL30.*;

/**
 * A framebuffer that later passes sample: an RGBA8 colour texture (linear, clamped) and a depth
 * renderbuffer. Used for the water's reflection and refraction. {@link #ensureSize} reallocates on resize.
 */
public final class RenderTarget implements AutoCloseable {
    private int fbo;
    private int colour;
    private int depth;
    private int width;
    private int height;

    /** Makes the target width x height (at least 1 x 1), reallocating only when the size changes. */
    public void ensureSize(int w, int h) {
        w = Math.max(1, w);
        h = Math.max(1, h);
        if (w == width && h == height && fbo != 0) return;
        close();
        width = w;
        height = h;
        int previous = glGetInteger(GL_FRAMEBUFFER_BINDING);
        fbo = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        colour = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, colour);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, (java.nio.ByteBuffer) null);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_2D, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
        depth = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, previous);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            close();
            throw new RenderException(String.format("A %dx%d render target is incomplete: 0x%X", w, h, status));
        }
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** The framebuffer object (0 before the first {@link #ensureSize}). */
    public int framebuffer() {
        return fbo;
    }

    /** Binds the target for drawing with a full viewport. */
    public void bind() {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
    }

    /** Binds the colour texture to texture unit {@code unit}. */
    public void bindColour(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, colour);
    }

    @Override
    public void close() {
        if (fbo != 0) {
            glDeleteFramebuffers(fbo);
            glDeleteTextures(colour);
            glDeleteRenderbuffers(depth);
        }
        fbo = colour = depth = 0;
        width = height = 0;
    }
}
