package minigolf.render;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.lwjgl.stb.STBImageWrite.stbi_write_png;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/** Writes GL read-back pixels as PNG with STB image write. */
public final class Png {
    private Png() {
    }

    /**
     * Writes {@code width x height} RGBA pixels given bottom row first (as glReadPixels returns them)
     * to {@code file}, top row first as images are stored. Creates the parent directory.
     */
    public static void writeBottomUp(Path file, int width, int height, ByteBuffer rgba) {
        try {
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) Files.createDirectories(parent);
        } catch (java.io.IOException e) {
            throw new RenderException("Cannot create the directory for " + file, e);
        }
        int stride = width * 4;
        ByteBuffer flipped = memAlloc(stride * height);
        try {
            for (int row = 0; row < height; row++) {
                ByteBuffer src = rgba.slice((height - 1 - row) * stride, stride);
                flipped.put(row * stride, src, 0, stride);
            }
            if (!stbi_write_png(file.toAbsolutePath().toString(), width, height, 4, flipped, stride)) {
                throw new RenderException("stbi_write_png could not write " + file);
            }
        } finally {
            memFree(flipped);
        }
    }
}
