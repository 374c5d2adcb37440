package minigolf.physics;

/**
 * The end of one stroke. {@code end} is the rest point, or where the ball entered water, left
 * the bounds or dropped into the hole.
 */
public record ShotResult(Outcome outcome, double endX, double endY, double time, int steps) {
}
