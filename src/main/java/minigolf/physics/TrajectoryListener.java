package minigolf.physics;

/**
 * Receives the ball's state after every integration step and, inside a step longer than dt,
 * about every dt along its path (for CSV output, drawing and the bots' path tracing), and the
 * stroke's events.
 */
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

    /**
     * Whether the listener wants the stroke's events and the states along a long step's path; true
     * by default. A listener that only counts steps (a bot's cancellation check) says false: it
     * then hears each step's end only, and no event is built for it.
     */
    default boolean wantsDetail() {
        return true;
    }
}
