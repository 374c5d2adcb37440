package minigolf.physics;

/** Receives the ball's state after every integration step (for CSV output and drawing). */
@FunctionalInterface
public interface TrajectoryListener {
    /** The state in the plane: position and horizontal velocity. */
    void onStep(double t, double x, double y, double vx, double vy);

    /**
     * The full state: (x, y, z) is the ball's contact point (its lowest point; the centre is
     * ballRadius above it) and (vx, vy, vz) its velocity. By default passes the plane part on.
     */
    default void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
        onStep(t, x, y, vx, vy);
    }

    /** An event of the stroke (launch, bounce, collision, ...), in time order. */
    default void onEvent(StrokeEvent event) {
    }
}
