package minigolf.physics;

import java.util.ArrayDeque;

/**
 * Holds a stroke's reports back until the game's frames reach their time: a step may run ahead of
 * the frame being drawn (steps are longer than frames where the path is easy), and a sound or a
 * splash must come when the drawn ball gets there, not a step early. Only the game's strokes,
 * driven frame by frame, use it; the bots' listener hears everything as it is computed.
 */
final class FrameDelay implements TrajectoryListener {
    private final TrajectoryListener listener;
    /** Reports not passed on yet, in time order: double[7] states and events. */
    private final ArrayDeque<Object> pending = new ArrayDeque<>();

    FrameDelay(TrajectoryListener listener) {
        this.listener = listener;
    }

    @Override
    public void onStep(double t, double x, double y, double vx, double vy) {
        onState(t, x, y, Double.NaN, vx, vy, Double.NaN);
    }

    @Override
    public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
        pending.add(new double[] {t, x, y, z, vx, vy, vz});
    }

    @Override
    public void onEvent(StrokeEvent event) {
        pending.add(event);
    }

    /** Passes on every report up to time {@code until}, in order. */
    void release(double until) {
        while (!pending.isEmpty()) {
            Object next = pending.peek();
            double t = next instanceof double[] s ? s[0] : ((StrokeEvent) next).t();
            if (t > until) return;
            pending.poll();
            if (next instanceof double[] s) {
                listener.onState(s[0], s[1], s[2], s[3], s[4], s[5], s[6]);
            } else {
                listener.onEvent((StrokeEvent) next);
            }
        }
    }
}
