package minigolf.physics;

import java.util.List;

/**
 * The end of one stroke; {@code state} is the course after it (the bricks it left standing). {@code end} is the rest point, or where the ball entered water, left
 * the bounds or dropped into the hole; {@code endZ} is the height of the ball's lowest point there
 * (NaN where unknown). {@code events} is empty unless the stroke was asked to record them.
 */
public record ShotResult(Outcome outcome, double endX, double endY, double time, int steps, double endZ,
                         List<StrokeEvent> events, CourseState state) {
    public ShotResult {
        events = List.copyOf(events);
        if (state == null) state = CourseState.NONE;
    }

    /** A result on a course without bricks. */
    public ShotResult(Outcome outcome, double endX, double endY, double time, int steps, double endZ,
                      List<StrokeEvent> events) {
        this(outcome, endX, endY, time, steps, endZ, events, CourseState.NONE);
    }

    /** A result without height or events. */
    public ShotResult(Outcome outcome, double endX, double endY, double time, int steps) {
        this(outcome, endX, endY, time, steps, Double.NaN, List.of());
    }
}
