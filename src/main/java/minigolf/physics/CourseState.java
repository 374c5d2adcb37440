package minigolf.physics;

import java.util.Arrays;
import java.util.List;
import minigolf.course.Brick;
import minigolf.course.Course;

/**
 * What the strokes on a hole have changed on the course and what lasts until the hole ends: the
 * hits each breakable brick can still take (0 = broken, gone). Immutable; a stroke starts from
 * its world's state ({@link World#state()}) and its result holds the state after it
 * ({@link ShotResult#state()}). Every hole starts again from {@link #initial}.
 */
public final class CourseState {
    /** The state of a course without bricks. */
    public static final CourseState NONE = new CourseState(new int[0]);

    private final int[] hitsLeft;

    private CourseState(int[] hitsLeft) {
        this.hitsLeft = hitsLeft;
    }

    /** Every brick standing with the hits the course file gives it. */
    public static CourseState initial(Course course) {
        List<Brick> bricks = course.bricks();
        if (bricks.isEmpty()) return NONE;
        int[] hits = new int[bricks.size()];
        for (int i = 0; i < hits.length; i++) hits[i] = bricks.get(i).hits();
        return new CourseState(hits);
    }

    /**
     * A state with these hits left, checked against the course: one entry per brick, each from 0 to
     * the brick's own hits.
     *
     * @throws IllegalArgumentException otherwise
     */
    public static CourseState of(Course course, int[] hitsLeft) {
        List<Brick> bricks = course.bricks();
        if (hitsLeft.length != bricks.size()) {
            throw new IllegalArgumentException("the course has " + bricks.size() + " bricks, the state " + hitsLeft.length);
        }
        for (int i = 0; i < hitsLeft.length; i++) {
            if (hitsLeft[i] < 0 || hitsLeft[i] > bricks.get(i).hits()) {
                throw new IllegalArgumentException("brick " + i + " takes " + bricks.get(i).hits() + " hits, the state says "
                        + hitsLeft[i] + " left");
            }
        }
        return hitsLeft.length == 0 ? NONE : new CourseState(hitsLeft.clone());
    }

    /** Number of bricks. */
    public int bricks() {
        return hitsLeft.length;
    }

    /** Hits brick i can still take; 0 when it is broken. */
    public int hitsLeft(int i) {
        return hitsLeft[i];
    }

    public boolean standing(int i) {
        return hitsLeft[i] > 0;
    }

    /** The hits left of every brick (a copy). */
    public int[] hitsLeft() {
        return hitsLeft.clone();
    }

    /** The state after a stroke that left the bricks with {@code after} (a stroke's own counts). */
    static CourseState after(CourseState before, int[] after) {
        return Arrays.equals(before.hitsLeft, after) ? before : new CourseState(after.clone());
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof CourseState s && Arrays.equals(hitsLeft, s.hitsLeft);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(hitsLeft);
    }

    @Override
    public String toString() {
        return "bricks " + Arrays.toString(hitsLeft);
    }
}
