package minigolf.texture;

/**
 * Tiling value noise and an integer hash for the procedural textures: lattice values come from a
 * hash of the lattice point modulo the period, so a tile repeats seamlessly. Deterministic.
 */
public final class Noise {
    private Noise() {
    }

    /** Smooth value noise at lattice coordinates (x, y), in [0, 1), repeating every {@code period} cells. */
    public static double value(double x, double y, int period) {
        int ix = (int) Math.floor(x), iy = (int) Math.floor(y);
        double fx = x - ix, fy = y - iy;
        double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
        double a = lattice(ix, iy, period), b = lattice(ix + 1, iy, period);
        double c = lattice(ix, iy + 1, period), d = lattice(ix + 1, iy + 1, period);
        double top = a + (b - a) * sx, bottom = c + (d - c) * sx;
        return top + (bottom - top) * sy;
    }

    /** The lattice value at (ix, iy): the same for points a period apart. */
    public static double lattice(int ix, int iy, int period) {
        return hash(Math.floorMod(ix, period), Math.floorMod(iy, period), period);
    }

    /** A pseudo-random value in [0, 1) for integer (x, y) and a seed. */
    public static double hash(int x, int y, int seed) {
        int h = x * 374761393 + y * 668265263 + seed * 1274126177;
        h = (h ^ (h >>> 13)) * 1274126177;
        h ^= h >>> 16;
        return (h & 0xFFFFFF) / (double) 0x1000000;
    }
}
