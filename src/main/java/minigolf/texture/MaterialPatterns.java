package minigolf.texture;

/**
 * The materials' surface detail, made in code: tiling RGBA8 images of grass, sand, wood, stone, rock
 * strata and snow. RGB is a brightness and tint factor for the material's own colour, stored halved
 * (128 means x1.0, so the shaders multiply by 2 and can brighten as well as darken); alpha is a
 * height (0 low, 255 high) that the high quality tier turns into bump normals. Every layer tiles
 * seamlessly (its noise repeats with the tile) and is the same every time (fixed seeds). Plain Java.
 */
public final class MaterialPatterns {
    /** The layers, in texture-array order (the shaders' LAYER_* constants). */
    public enum Layer {
        GRASS, SAND, WOOD, STONE, ROCK, SNOW,
        /** Soft patches a few cells across the tile: read at a large scale, the grass's and the ground's patchiness. */
        MOTTLE
    }

    private MaterialPatterns() {
    }

    /** All layers, {@code size x size} each, one after the other (size a multiple of 64). */
    public static byte[] all(int size) {
        Layer[] layers = Layer.values();
        byte[] out = new byte[layers.length * size * size * 4];
        for (Layer l : layers) System.arraycopy(layer(l, size), 0, out, l.ordinal() * size * size * 4, size * size * 4);
        return out;
    }

    /** One layer as RGBA8, {@code size x size} (a multiple of 64). */
    public static byte[] layer(Layer layer, int size) {
        if (size <= 0 || size % 64 != 0) throw new IllegalArgumentException("size must be a positive multiple of 64, got " + size);
        byte[] out = new byte[size * size * 4];
        double[] px = new double[4];
        for (int j = 0; j < size; j++) {
            for (int i = 0; i < size; i++) {
                double u = (i + 0.5) / size, v = (j + 0.5) / size;
                switch (layer) {
                    case GRASS -> grass(u, v, i, j, px);
                    case SAND -> sand(u, v, i, j, px);
                    case WOOD -> wood(u, v, px);
                    case STONE -> stone(u, v, px);
                    case ROCK -> rock(u, v, px);
                    case SNOW -> snow(u, v, i, j, px);
                    case MOTTLE -> mottle(u, v, px);
                }
                int k = 4 * (j * size + i);
                for (int c = 0; c < 3; c++) out[k + c] = toByte(px[c] * 0.5);
                out[k + 3] = toByte(px[3]);
            }
        }
        return out;
    }

    /** Fine blades (high-frequency noise, stretched a little) and small clumps; larger patches come from a second, coarser read. */
    private static void grass(double u, double v, int i, int j, double[] px) {
        double blades = fbm(u * 1.0, v * 0.7, 48, 2);
        double clumps = Noise.value(u * 16, v * 16, 16);
        double speck = Noise.hash(i, j, 11) < 0.03 ? 0.08 : 0;
        double b = 0.84 + 0.28 * blades + 0.08 * (clumps - 0.5) + speck;
        px[0] = b * (1 + 0.03 * (clumps - 0.5));
        px[1] = b;
        px[2] = b * (1 - 0.04 * (clumps - 0.5));
        px[3] = 0.25 + 0.6 * blades + 0.15 * clumps;
    }

    /** Grains (a per-texel scatter) over soft wind ripples. */
    private static void sand(double u, double v, int i, int j, double[] px) {
        double grain = Noise.hash(i, j, 23) - 0.5;
        double ripple = 0.5 + 0.5 * Math.sin(2 * Math.PI * (6 * v + 0.35 * Noise.value(u * 4, v * 4, 4)));
        double mottle = Noise.value(u * 6, v * 6, 6);
        double b = 0.90 + 0.20 * grain + 0.08 * ripple + 0.08 * (mottle - 0.5);
        px[0] = b;
        px[1] = b * (1 - 0.02 * grain);
        px[2] = b * (1 - 0.05 * grain);
        px[3] = 0.55 * ripple + 0.3 * (grain + 0.5) + 0.15 * mottle;
    }

    /**
     * Two boards across the tile (v), running along u, with staggered butt joints: grain lines
     * bent by noise, darker seams sunk into the height.
     */
    private static void wood(double u, double v, double[] px) {
        int board = v < 0.5 ? 0 : 1;
        double bv = (v - 0.5 * board) * 2; // 0..1 across the board
        double joint = board == 0 ? 0.0 : 0.5;
        double du = Math.abs(((u - joint) % 1 + 1) % 1 - 0.5); // 0.5 at the joint
        double seam = Math.max(smoothstep(0.06, 0.0, Math.min(bv, 1 - bv)), smoothstep(0.492, 0.5, du));
        double warp = Noise.value(u * 4, v * 8 + board * 3, 4) * 2.2;
        double grain = 0.5 + 0.5 * Math.sin(2 * Math.PI * (bv * 5 + warp + board * 0.37));
        double streak = Noise.value(u * 2, v * 64, 2);
        double boardTint = board == 0 ? 1.0 : 0.93;
        double b = boardTint * (0.86 + 0.16 * grain + 0.10 * (streak - 0.5)) * (1 - 0.45 * seam);
        px[0] = b * 1.02;
        px[1] = b;
        px[2] = b * 0.96;
        px[3] = (0.75 + 0.2 * grain) * (1 - seam);
    }

    /** Dressed blocks in running bond (4 courses, 2 blocks each), mortar joints sunk, each block its own shade. */
    private static void stone(double u, double v, double[] px) {
        int row = (int) Math.floor(v * 4);
        double rv = v * 4 - row;
        double shifted = u * 2 + (row % 2 == 1 ? 0.5 : 0);
        int col = (int) Math.floor(shifted);
        double ru = shifted - col;
        col = Math.floorMod(col, 2);
        double edge = Math.min(Math.min(ru, 1 - ru) * 0.5, Math.min(rv, 1 - rv) * 0.25) * 4; // ~texel-even distances
        double mortar = smoothstep(0.045, 0.02, edge);
        double bevel = smoothstep(0.02, 0.12, edge);
        double tint = 0.88 + 0.22 * Noise.hash(col, row, 37);
        double pits = fbm(u, v, 32, 3);
        double b = mix(tint * (0.86 + 0.28 * pits), 0.62, mortar);
        px[0] = b;
        px[1] = b * 0.99;
        px[2] = b * 0.97;
        px[3] = (1 - mortar) * (0.5 + 0.3 * bevel + 0.2 * pits);
    }

    /** Layered rock: strata bands along u, gently wavy, of varied shades, with fine grain and a few ledges. */
    private static void rock(double u, double v, double[] px) {
        double wobble = 0.03 * Noise.value(u * 4, v * 2, 4) + 0.008 * Noise.value(u * 16, v * 8, 16);
        double h = v + wobble;
        double band = Noise.value(0.5, h * 10, 10) * 0.7 + Noise.value(0.25, h * 40, 40) * 0.3;
        double streak = Noise.value(u * 8, h * 64, 8);
        double fine = fbm(u, v, 32, 2);
        double ledge = smoothstep(0.75, 0.95, Noise.value(0.5, h * 5, 5));
        double b = (0.78 + 0.36 * band) * (0.9 + 0.12 * streak + 0.1 * (fine - 0.5)) * (1 - 0.18 * ledge);
        px[0] = b * (1 + 0.05 * (band - 0.5));
        px[1] = b;
        px[2] = b * (1 - 0.05 * (band - 0.5));
        px[3] = 0.55 * band + 0.25 * fine + 0.2 * streak;
    }

    /** Patches: lighter and darker, a little yellower where lighter (dry), from two octaves. */
    private static void mottle(double u, double v, double[] px) {
        double m = fbm(u, v, 4, 3);
        double b = 0.86 + 0.28 * m;
        px[0] = b * (1 + 0.08 * (m - 0.5));
        px[1] = b;
        px[2] = b * (1 - 0.10 * (m - 0.5));
        px[3] = m;
    }

    /** Soft drifts and a few sparkling crystals. */
    private static void snow(double u, double v, int i, int j, double[] px) {
        double drift = fbm(u, v, 4, 3);
        double sparkle = Noise.hash(i, j, 53) > 0.985 ? 0.35 : 0;
        double b = 0.92 + 0.10 * drift + sparkle;
        px[0] = b * 0.98;
        px[1] = b * 0.99;
        px[2] = b * 1.02;
        px[3] = drift;
    }

    /** Octaves of value noise from {@code cells} lattice cells across the tile, each twice as fine, in [0, 1). */
    static double fbm(double u, double v, int cells, int octaves) {
        double sum = 0, amp = 0.5, norm = 0;
        for (int o = 0; o < octaves; o++) {
            sum += amp * Noise.value(u * cells, v * cells, cells);
            norm += amp;
            cells *= 2;
            amp *= 0.5;
        }
        return sum / norm;
    }

    static double smoothstep(double e0, double e1, double x) {
        double t = Math.max(0, Math.min(1, (x - e0) / (e1 - e0)));
        return t * t * (3 - 2 * t);
    }

    private static double mix(double a, double b, double t) {
        return a + (b - a) * t;
    }

    private static byte toByte(double x) {
        return (byte) Math.max(0, Math.min(255, Math.round(x * 255)));
    }
}
