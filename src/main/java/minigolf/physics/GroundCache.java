package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * The terrain's last full sample (height and slope) and where it was taken. A rolling step's end
 * is sampled up to three times (the long step's last stage, the check for water there, the next
 * step's start); the terrain gives the same numbers every time, so one sample serves all three.
 */
final class GroundCache {
    private final Terrain terrain;
    private final double[] sample = new double[3];
    private double x = Double.NaN, y = Double.NaN;

    GroundCache(Terrain terrain) {
        this.terrain = terrain;
    }

    /** Samples (qx, qy) unless it is the point sampled last; h, dh/dx, dh/dy are then in {@link #values()}. */
    double[] at(double qx, double qy) {
        if (qx != x || qy != y) {
            terrain.sample(qx, qy, sample);
            x = qx;
            y = qy;
        }
        return sample;
    }

    /** Remembers a sample of (qx, qy) taken elsewhere. */
    void keep(double qx, double qy, double h, double hx, double hy) {
        x = qx;
        y = qy;
        sample[0] = h;
        sample[1] = hx;
        sample[2] = hy;
    }

    /** The last sample: h, dh/dx, dh/dy. */
    double[] values() {
        return sample;
    }
}
