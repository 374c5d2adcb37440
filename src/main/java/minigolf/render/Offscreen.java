package minigolf.render;

import minigolf.io.AtomicFile;

import java.nio.ByteBuffer;
import java.nio.file.Path;

import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/**
 * Off-screen rendering for stills, benchmarks and tests: a hidden window (for the GL context) and a
 * width x height framebuffer. Usage: {@link #bind()}, draw, then {@link #savePng} or {@link #finish()}.
 */
public final class Offscreen implements AutoCloseable {
    private final Window window;
    private final Framebuffer target;

    public Offscreen(int width, int height, int samples) {
        window = new Window("Minigolf off-screen", 64, 64, Window.Options.hidden());
        try {
            target = new Framebuffer(width, height, samples);
        } catch (RuntimeException e) {
            window.close();
            throw e;
        }
    }

    public int width() {
        return target.width();
    }

    public int height() {
        return target.height();
    }

    /** Makes the framebuffer the render target, with a full viewport. */
    public void bind() {
        target.bind();
    }

    /** Waits until the GPU has finished the frame (for timing). */
    public void finish() {
        org.lwjgl.opengl.GL11.glFinish();
    }

    /** Resolves the frame and writes it as PNG, atomically (the old file stays whole if writing fails). */
    public void savePng(Path png) {
        byte[] encoded = encodePng();
        try {
            Path parent = png.toAbsolutePath().getParent();
            if (parent != null) java.nio.file.Files.createDirectories(parent);
            AtomicFile.write(png, encoded);
        } catch (java.io.IOException e) {
            throw new RenderException("cannot write " + png + ": " + e.getMessage(), e);
        }
    }

    /** Resolves the frame and encodes it as PNG bytes. */
    public byte[] encodePng() {
        int w = target.width(), h = target.height();
        target.resolve();
        ByteBuffer pixels = memAlloc(w * h * 4);
        try {
            target.readPixels(pixels);
            return Png.encodeBottomUp(w, h, pixels);
        } finally {
            memFree(pixels);
        }
    }

    @Override
    public void close() {
        target.close();
        window.close();
    }
}
