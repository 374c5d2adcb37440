package minigolf.course;

import java.util.List;

/**
 * A teleport (course file field {@code teleports}): a rolling ball that enters {@code entry}
 * appears at one of the {@code exits} with the same speed. With several exits it takes them in
 * turn within a stroke (the first entry of a stroke the first exit, the next the second, ...).
 */
public record Teleport(Shape entry, List<Exit> exits) {
    public Teleport {
        exits = List.copyOf(exits);
    }

    /**
     * Where the ball comes out. With {@code directionDeg} null it keeps its direction; otherwise it
     * leaves at that angle (degrees counter-clockwise from +x), with its speed.
     */
    public record Exit(Vec2 position, Double directionDeg) {
    }
}
