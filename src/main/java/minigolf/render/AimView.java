package minigolf.render;

/**
 * The aiming arrow: it starts at the ball's contact point (x, y, z) and lies on the ground in the
 * direction (dirX, dirY) (need not be unit length). {@code power01} in [0, 1] sets its length and
 * colour, green (soft) to red (full power); values outside are clamped.
 */
public record AimView(float x, float y, float z, float dirX, float dirY, float power01) {
}
