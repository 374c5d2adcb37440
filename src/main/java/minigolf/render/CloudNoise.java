package minigolf.render;

import minigolf.texture.Noise;

/**
 * The sky's cloud layer as a tiling texture, made once in code: red is fractal value noise (four
 * octaves, each twice the frequency of the last) for cloud cover, green one octave of value noise at
 * twice the base frequency for the clouds' shading. The sky shader used to compute the same noise per
 * pixel (20 hashes a pixel, 6-8 ms a frame on llvmpipe); one texture fetch replaces it. Lattice
 * values come from an integer hash of the lattice point modulo the period, so the tile repeats
 * seamlessly. Plain Java, deterministic.
 */
public final class CloudNoise {
    /** Base-octave lattice cells across the tile. */
    public static final int PERIOD = 16;
    public static final int OCTAVES = 4;

    private CloudNoise() {
    }

    /** RGBA8 pixels of a {@code size x size} tile (size a multiple of PERIOD * 2^(OCTAVES-1)); blue and alpha 255. */
    public static byte[] rgba(int size) {
        if (size <= 0 || size % (PERIOD << (OCTAVES - 1)) != 0) {
            throw new IllegalArgumentException("size must be a positive multiple of " + (PERIOD << (OCTAVES - 1)));
        }
        byte[] out = new byte[size * size * 4];
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double u = (double) i / size, v = (double) j / size;
                int k = 4 * (j * size + i);
                out[k] = toByte(fbm(u, v));
                out[k + 1] = toByte(noise(u * 2 * PERIOD, v * 2 * PERIOD, 2 * PERIOD));
                out[k + 2] = (byte) 255;
                out[k + 3] = (byte) 255;
            }
        }
        return out;
    }

    /** Cloud cover at tile coordinates (u, v) in [0, 1): sum of amplitude-halving octaves, in [0, 1). */
    public static double fbm(double u, double v) {
        double sum = 0, amp = 0.5;
        int cells = PERIOD;
        for (int o = 0; o < OCTAVES; o++) {
            sum += amp * noise(u * cells, v * cells, cells);
            cells *= 2;
            amp *= 0.5;
        }
        return sum / (1 - Math.pow(0.5, OCTAVES)); // rescaled so the octaves' sum spans [0, 1)
    }

    /** Smooth value noise at lattice coordinates (x, y), repeating every {@code period} cells. */
    public static double noise(double x, double y, int period) {
        return Noise.value(x, y, period);
    }

    private static byte toByte(double x) {
        return (byte) Math.max(0, Math.min(255, Math.round(x * 255)));
    }
}
