package minigolf.terrain;

/**
 * The green's surface z = h(x, y). Water is wherever h < 0. Implementations are immutable and
 * safe to share between threads (bots simulate in parallel).
 */
public interface Terrain {
    double height(double x, double y);

    /** Writes h, dh/dx and dh/dy at (x, y) into out[0], out[1], out[2]. */
    void sample(double x, double y, double[] out);

    /**
     * Whether the surface is smooth wherever it is finite (no crease, no cell edge where the
     * curvature jumps): the engine takes long steps only there. False unless known.
     */
    default boolean isSmooth() {
        return false;
    }
}
