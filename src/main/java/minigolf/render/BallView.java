package minigolf.render;

/**
 * A ball to draw. (x, y, z) is its contact point, as physics reports it (a rolling ball has
 * z = h(x, y)); the sphere is drawn centred {@link ObjectsPass#visualBallRadius()} above it.
 * The colour is linear RGB in [0, 1].
 */
public record BallView(float x, float y, float z, float red, float green, float blue) {
    /** A white ball resting on the ground at (x, y, ground). */
    public static BallView white(double x, double y, double ground) {
        return new BallView((float) x, (float) y, (float) ground, 1f, 1f, 1f);
    }
}
