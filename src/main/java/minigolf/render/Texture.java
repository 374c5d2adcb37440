package minigolf.render;

import org.lwjgl.system.MemoryStack;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.IntBuffer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL13.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13.glActiveTexture;
import static org.lwjgl.opengl.GL30.glGenerateMipmap;
import static org.lwjgl.stb.STBImage.*;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/** A 2D texture decoded with STB image from {@code /textures/NAME} on the classpath, RGBA8, mipmapped. */
public final class Texture implements AutoCloseable {
    private final int id;
    private final int width;
    private final int height;

    private Texture(int id, int width, int height) {
        this.id = id;
        this.width = width;
        this.height = height;
    }

    /** Loads {@code /textures/NAME}; {@code repeat} tiles it, else its edges are clamped. */
    public static Texture load(String name, boolean repeat) {
        byte[] bytes;
        try (InputStream in = Texture.class.getResourceAsStream("/textures/" + name)) {
            if (in == null) throw new RenderException("Texture '/textures/" + name + "' is not on the classpath");
            bytes = in.readAllBytes();
        } catch (IOException e) {
            throw new RenderException("Could not read texture '/textures/" + name + "'", e);
        }
        ByteBuffer encoded = memAlloc(bytes.length);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            encoded.put(bytes).flip();
            IntBuffer w = stack.mallocInt(1), h = stack.mallocInt(1), c = stack.mallocInt(1);
            ByteBuffer pixels = stbi_load_from_memory(encoded, w, h, c, 4);
            if (pixels == null) {
                throw new RenderException("Texture '/textures/" + name + "' could not be decoded: " + stbi_failure_reason());
            }
            try {
                return upload(w.get(0), h.get(0), pixels, repeat);
            } finally {
                stbi_image_free(pixels);
            }
        } finally {
            memFree(encoded);
        }
    }

    /**
     * A texture from RGBA8 pixels made in code (rows bottom to top, {@code width * height * 4} bytes),
     * mipmapped; {@code repeat} tiles it, else its edges are clamped.
     */
    public static Texture fromPixels(int width, int height, byte[] rgba, boolean repeat) {
        if (rgba.length != width * height * 4) {
            throw new IllegalArgumentException("expected " + width * height * 4 + " bytes, got " + rgba.length);
        }
        ByteBuffer pixels = memAlloc(rgba.length);
        try {
            pixels.put(rgba).flip();
            return upload(width, height, pixels, repeat);
        } finally {
            memFree(pixels);
        }
    }

    private static Texture upload(int width, int height, ByteBuffer pixels, boolean repeat) {
        int id = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, id);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        glGenerateMipmap(GL_TEXTURE_2D);
        int wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindTexture(GL_TEXTURE_2D, 0);
        return new Texture(id, width, height);
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Binds to texture unit {@code unit}. */
    public void bind(int unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, id);
    }

    @Override
    public void close() {
        glDeleteTextures(id);
    }
}
