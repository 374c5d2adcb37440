package minigolf.render;

import java.nio.ByteBuffer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

/**
 * An off-screen render target: RGBA8 colour and 24-bit depth renderbuffers. With {@code samples > 1}
 * it renders multisampled and {@link #resolve()} blits into a single-sampled buffer to read back.
 */
public final class Framebuffer implements AutoCloseable {
    private final int width;
    private final int height;
    private final int samples;
    private final int fbo;
    private final int colour;
    private final int depth;
    private final int resolveFbo;
    private final int resolveColour;

    public Framebuffer(int width, int height, int requestedSamples) {
        this.width = width;
        this.height = height;
        int max = glGetInteger(GL_MAX_SAMPLES);
        this.samples = requestedSamples > 1 ? Math.min(requestedSamples, max) : 0;
        fbo = glGenFramebuffers();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        colour = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, colour);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
        depth = glGenRenderbuffers();
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        check("scene");
        if (samples > 1) {
            resolveFbo = glGenFramebuffers();
            glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo);
            resolveColour = glGenRenderbuffers();
            glBindRenderbuffer(GL_RENDERBUFFER, resolveColour);
            glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
            glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolveColour);
            check("resolve");
        } else {
            resolveFbo = 0;
            resolveColour = 0;
        }
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    private void check(String which) {
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            close();
            throw new RenderException(String.format("The %s framebuffer (%dx%d, %d samples) is incomplete: 0x%X",
                    which, width, height, samples, status));
        }
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int samples() {
        return samples;
    }

    public void bind() {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, width, height);
    }

    /** Makes the rendered image readable (a blit when multisampled). */
    public void resolve() {
        if (samples > 1) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo);
            glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    /** Reads the resolved RGBA pixels, bottom row first (GL order), into {@code dest} (width*height*4 bytes). */
    public void readPixels(ByteBuffer dest) {
        if (dest.remaining() < width * height * 4) throw new IllegalArgumentException("buffer too small");
        glBindFramebuffer(GL_READ_FRAMEBUFFER, samples > 1 ? resolveFbo : fbo);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, dest);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }

    @Override
    public void close() {
        glDeleteFramebuffers(fbo);
        glDeleteRenderbuffers(colour);
        glDeleteRenderbuffers(depth);
        if (resolveFbo != 0) {
            glDeleteFramebuffers(resolveFbo);
            glDeleteRenderbuffers(resolveColour);
        }
    }
}
