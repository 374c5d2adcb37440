package minigolf.render;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The short trail behind a rolling ball: where it was over the last {@link #SECONDS}, oldest
 * first. Plain Java; the objects pass draws it as dots that shrink towards its old end, so it fades.
 */
public final class BallTrail {
    /** How long a point stays in the trail, in seconds of the animation. */
    public static final double SECONDS = 0.45;
    /** Points closer together than this (metres) are not kept twice. */
    static final double MIN_STEP = 0.01;

    private final Deque<double[]> points = new ArrayDeque<>();

    /** The ball was at (x, y, z) at time t (seconds, increasing). */
    public void add(double t, double x, double y, double z) {
        double[] last = points.peekLast();
        if (last != null && Math.hypot(x - last[1], y - last[2]) < MIN_STEP) {
            last[0] = t; // still: the end stays fresh
        } else {
            points.addLast(new double[]{t, x, y, z});
        }
        while (points.size() > 1 && points.peekFirst()[0] < t - SECONDS) points.removeFirst();
    }

    public void clear() {
        points.clear();
    }

    public boolean isEmpty() {
        return points.size() < 2;
    }

    /** The trail as (x, y, z) triplets, oldest first; empty when there is none. */
    public float[] path() {
        if (isEmpty()) return new float[0];
        float[] out = new float[3 * points.size()];
        int i = 0;
        for (double[] p : points) {
            out[i++] = (float) p[1];
            out[i++] = (float) p[2];
            out[i++] = (float) p[3];
        }
        return out;
    }
}
