package minigolf.course;

/**
 * A breakable brick (course file field {@code bricks}): an upright box from {@code min} to
 * {@code max} (absolute heights) that the ball bounces off with {@code restitution} and that
 * breaks after {@code hits} contacts. What is left of each brick lasts from stroke to stroke on
 * a hole ({@code physics.CourseState}); the course file holds the bricks as the hole starts.
 */
public record Brick(Vec3 min, Vec3 max, int hits, double restitution) {
    /** The most hits a brick may take (the classic game's full brick takes 4). */
    public static final int MAX_HITS = 100;
    /** Restitution used when the field is not given (the classic game's bricks). */
    public static final double DEFAULT_RESTITUTION = 0.9;

    public Brick {
        if (hits < 1 || hits > MAX_HITS) throw new IllegalArgumentException("hits must be 1 to " + MAX_HITS + ", got " + hits);
    }

    /** The brick as the obstacle the ball meets while it stands. */
    public Obstacle.Box box() {
        return new Obstacle.Box(min, max, 0, restitution);
    }
}
