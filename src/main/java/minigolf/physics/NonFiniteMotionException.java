package minigolf.physics;

import java.util.Locale;

/**
 * The ball reached a point where the terrain's height or slope is not a finite number (sqrt(x)
 * left of 0, 1/x at 0), or where friction or slope is so large that its motion overflows. A
 * fact about the course, not a bug: the command line reports it in one line with exit code 2.
 */
public final class NonFiniteMotionException extends RuntimeException {
    NonFiniteMotionException(String what, double x, double y) {
        super(String.format(Locale.ROOT, "%s at (%.6g, %.6g): the stroke cannot go on", what, x, y));
    }

    static NonFiniteMotionException terrain(double x, double y) {
        return new NonFiniteMotionException("the terrain's height or slope is not a finite number", x, y);
    }

    static NonFiniteMotionException unresolved(double x, double y) {
        return new NonFiniteMotionException(
                "the ball's path cannot be followed (the ground changes faster than any step can resolve)", x, y);
    }

    static NonFiniteMotionException motion(double x, double y) {
        return new NonFiniteMotionException(
                "the ball's motion overflows (friction or slope too large, or a terrain that is not finite nearby)", x, y);
    }
}
