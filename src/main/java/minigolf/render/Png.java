package minigolf.render;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.stb.STBImageWrite.stbi_write_png;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/** Writes GL read-back pixels as PNG with STB image write. */
public final class Png {
    private Png() {
    }

    /** Encodes RGBA pixels given bottom row first (as glReadPixels returns them) as PNG bytes, top row first. */
    public static byte[] encodeBottomUp(int width, int height, ByteBuffer rgba) {
        int stride = width * 4;
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        ByteBuffer flipped = memAlloc(stride * height);
        try (org.lwjgl.stb.STBIWriteCallback sink = org.lwjgl.stb.STBIWriteCallback.create((context, data, size) -> {
            byte[] chunk = new byte[size];
            org.lwjgl.stb.STBIWriteCallback.getData(data, size).get(chunk);
            out.write(chunk, 0, size);
        })) {
            for (int row = 0; row < height; row++) {
                flipped.put(row * stride, rgba, (height - 1 - row) * stride, stride);
            }
            if (!org.lwjgl.stb.STBImageWrite.stbi_write_png_to_func(sink, 0L, width, height, 4, flipped, stride)) {
                throw new RenderException("stbi_write_png_to_func failed for a " + width + "x" + height + " image");
            }
        } finally {
            memFree(flipped);
        }
        return out.toByteArray();
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

    /** Reads the current window's back buffer (width x height pixels) and writes it as a PNG. */
    public static void saveBackBuffer(Path file, int width, int height) {
        ByteBuffer pixels = memAlloc(width * height * 4);
        try {
            glReadBuffer(GL_BACK);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            writeBottomUp(file, width, height, pixels);
        } finally {
            memFree(pixels);
        }
    }
}
