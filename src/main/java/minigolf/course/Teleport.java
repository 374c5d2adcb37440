package minigolf.course;

import java.util.List;

/**
 * A teleport (course file field {@code teleports}): a rolling ball that enters {@code entry}
 * appears at one of the {@code exits} with the same speed. With several exits it takes them in
 * turn within a stroke (the first entry of a stroke the first exit, the next the second, ...), or,
 * with a {@code seed}, draws one (as the classic game's teleports): the draw is a function of the
 * seed, the stroke's shot and how many times the stroke has used the teleport, so a replay or a
 * bot's simulation of the same shot draws the same exits.
 */
public record Teleport(Shape entry, List<Exit> exits, Long seed) {
    public Teleport {
        exits = List.copyOf(exits);
    }

    /** A teleport that takes its exits in turn. */
    public Teleport(Shape entry, List<Exit> exits) {
        this(entry, exits, null);
    }

    /**
     * The exit a ball takes on its {@code use}-th entry (from 0) in a stroke whose shot is
     * summarised by {@code strokeKey}: in turn without a seed, else a draw.
     */
    public Exit exit(long strokeKey, int use) {
        int n = exits.size();
        if (seed == null) return exits.get(use % n);
        // SplitMix64's finaliser over the seed, the shot and the use: a well-mixed 64-bit draw.
        long z = seed * 0x9E3779B97F4A7C15L + strokeKey * 0xBF58476D1CE4E5B9L + use * 0x94D049BB133111EBL;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        z ^= z >>> 31;
        return exits.get((int) Math.floorMod(z, (long) n));
    }

    /**
     * Where the ball comes out. With {@code directionDeg} null it keeps its direction; otherwise it
     * leaves at that angle (degrees counter-clockwise from +x), with its speed.
     */
    public record Exit(Vec2 position, Double directionDeg) {
    }
}
