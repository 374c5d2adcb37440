package minigolf.render;

import org.lwjgl.system.MemoryStack;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Path;

import static org.lwjgl.stb.STBImage.*;

/** A PNG read back with STB image, for checking pixels. Rows top first. */
record Pixels(int width, int height, int[] rgb) {
    static Pixels read(Path png) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer w = stack.mallocInt(1), h = stack.mallocInt(1), c = stack.mallocInt(1);
            ByteBuffer data = stbi_load(png.toAbsolutePath().toString(), w, h, c, 4);
            if (data == null) throw new AssertionError("cannot read " + png + ": " + stbi_failure_reason());
            try {
                int[] rgb = new int[w.get(0) * h.get(0)];
                for (int i = 0; i < rgb.length; i++) {
                    rgb[i] = ((data.get(4 * i) & 0xff) << 16) | ((data.get(4 * i + 1) & 0xff) << 8) | (data.get(4 * i + 2) & 0xff);
                }
                return new Pixels(w.get(0), h.get(0), rgb);
            } finally {
                stbi_image_free(data);
            }
        }
    }

    int r(int x, int y) {
        return (rgb[y * width + x] >> 16) & 0xff;
    }

    int g(int x, int y) {
        return (rgb[y * width + x] >> 8) & 0xff;
    }

    int b(int x, int y) {
        return rgb[y * width + x] & 0xff;
    }

    /** Water: blue clearly dominant, but not the pale sky (whose red is high). */
    boolean isWater(int x, int y) {
        int r = r(x, y), g = g(x, y), b = b(x, y);
        return b > r + 60 && b > g + 15 && r < 110;
    }

    boolean isNearWhite(int x, int y) {
        return r(x, y) > 200 && g(x, y) > 200 && b(x, y) > 200;
    }

    String describe(int x, int y) {
        return "(" + r(x, y) + "," + g(x, y) + "," + b(x, y) + ") at " + x + "," + y;
    }
}
