package minigolf.physics;

/**
 * The bricks during one stroke: how many hits each can still take. Every contact with a standing
 * brick counts one hit; the hit that leaves it none still bounces the ball, and from then on the
 * brick is gone for the rest of the stroke and for the strokes after (the classic game's bricks).
 */
final class BrickHits {
    private final int[] left;
    /** Broken bricks, by index: the sweeps pass over them. */
    final boolean[] gone;
    private CourseState start;

    BrickHits(int bricks) {
        left = new int[bricks];
        gone = new boolean[bricks];
    }

    void start(CourseState state) {
        start = state;
        for (int i = 0; i < left.length; i++) {
            left[i] = state.hitsLeft(i);
            gone[i] = left[i] == 0;
        }
    }

    /** Brick i was hit. */
    void hit(int i) {
        if (left[i] > 0 && --left[i] == 0) gone[i] = true;
    }

    /** The state after the stroke so far. */
    CourseState state() {
        return CourseState.after(start, left);
    }
}
