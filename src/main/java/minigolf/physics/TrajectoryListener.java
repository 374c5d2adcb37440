package minigolf.physics;

/** Receives the ball's state after every integration step (for CSV output and drawing). */
@FunctionalInterface
public interface TrajectoryListener {
    void onStep(double t, double x, double y, double vx, double vy);
}
