package minigolf.render;

/**
 * The aiming arrow: it starts at the ball's contact point (x, y, z) and lies on the ground in the
 * direction (dirX, dirY) (need not be unit length). {@code power01} in [0, 1] sets its length and
 * colour, green (soft) to red (full power); values outside are clamped. {@code guide}, if not null,
 * is the aim guide's path ((x, y, z) triplets, see {@code minigolf.game.AimGuide}), drawn as a
 * dotted line; views are compared by the array's identity, so keep the same array while the aim holds.
 */
public record AimView(float x, float y, float z, float dirX, float dirY, float power01, float[] guide) {
    /** An arrow without a guide. */
    public AimView(float x, float y, float z, float dirX, float dirY, float power01) {
        this(x, y, z, dirX, dirY, power01, null);
    }
}
