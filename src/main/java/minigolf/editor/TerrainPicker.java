package minigolf.editor;

import minigolf.course.Bounds;
import minigolf.terrain.Terrain;

/**
 * Mouse picking: where a ray (from the camera through the cursor) first meets the height field
 * inside the bounds. The ray is marched in steps of a fraction of the grid spacing until it is
 * below the surface, then the crossing is refined by bisection.
 */
public final class TerrainPicker {
    private static final int BISECTIONS = 30;
    /** The longest stretch of ray searched, in metres. */
    private static final double MAX_DISTANCE = 1000;

    private TerrainPicker() {
    }

    /**
     * The point {x, y, z} where the ray origin + t * direction (t &ge; 0) first meets z = h(x, y)
     * over the bounds, or null if it misses. {@code step} is the marching step in metres (e.g. half
     * the grid spacing: features narrower than that may be stepped over).
     */
    public static double[] pick(Terrain terrain, Bounds b, double ox, double oy, double oz, double dx, double dy,
                                double dz, double step) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (len == 0) return null;
        dx /= len;
        dy /= len;
        dz /= len;
        // Clip the ray to the bounds' box in x and y (slab test).
        double t0 = 0, t1 = Double.POSITIVE_INFINITY;
        double[] o = {ox, oy}, d = {dx, dy}, lo = {b.minX(), b.minY()}, hi = {b.maxX(), b.maxY()};
        for (int a = 0; a < 2; a++) {
            if (Math.abs(d[a]) < 1e-15) {
                if (o[a] < lo[a] || o[a] > hi[a]) return null;
            } else {
                double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
                t0 = Math.max(t0, Math.min(ta, tb));
                t1 = Math.min(t1, Math.max(ta, tb));
            }
        }
        // A ray straight up or down never leaves the slab: bound it (the camera is never that far away).
        t1 = Math.min(t1, t0 + MAX_DISTANCE);
        if (t0 > t1) return null;
        double prev = t0;
        if (above(terrain, ox, oy, oz, dx, dy, dz, prev) <= 0) return point(ox, oy, oz, dx, dy, dz, prev);
        for (double t = t0 + step; ; t += step) {
            double tt = Math.min(t, t1);
            if (above(terrain, ox, oy, oz, dx, dy, dz, tt) <= 0) {
                double a = prev, c = tt;
                for (int k = 0; k < BISECTIONS; k++) {
                    double m = 0.5 * (a + c);
                    if (above(terrain, ox, oy, oz, dx, dy, dz, m) <= 0) c = m; else a = m;
                }
                return point(ox, oy, oz, dx, dy, dz, c);
            }
            if (tt >= t1) return null;
            prev = tt;
        }
    }

    private static double above(Terrain terrain, double ox, double oy, double oz, double dx, double dy, double dz, double t) {
        return oz + t * dz - terrain.height(ox + t * dx, oy + t * dy);
    }

    private static double[] point(double ox, double oy, double oz, double dx, double dy, double dz, double t) {
        return new double[]{ox + t * dx, oy + t * dy, oz + t * dz};
    }
}
