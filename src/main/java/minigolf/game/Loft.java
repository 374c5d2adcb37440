package minigolf.game;

/**
 * The loft of a stroke: how steeply the ball is hit upwards, from 0 degrees (a putt along the
 * ground) to {@link #MAX_DEGREES} (a steep chip). The player's drag chooses the direction and the
 * speed; the loft tilts that velocity up without changing its length, so the course's speed limit
 * holds for the whole vector (as {@code simulate --velocity VX,VY,VZ}).
 */
public final class Loft {
    public static final int MAX_DEGREES = 60;
    /** One notch of the mouse wheel or one key press. */
    public static final int STEP_DEGREES = 5;

    private Loft() {
    }

    /** {@code degrees} held to [0, MAX_DEGREES]. */
    public static int clamp(int degrees) {
        return Math.max(0, Math.min(MAX_DEGREES, degrees));
    }

    /** The loft after {@code notches} steps up (positive) or down (negative) from {@code degrees}. */
    public static int step(int degrees, int notches) {
        return clamp(degrees + notches * STEP_DEGREES);
    }

    /**
     * The shot (vx, vy, vz) for a ground aim (vx, vy), whose length is the chosen speed, tilted up by
     * {@code degrees}: the same direction over the ground, the same speed in all (at most
     * {@code maxSpeed}). At 0 degrees it is the aim itself, a putt.
     */
    public static double[] velocity(double vx, double vy, double degrees, double maxSpeed) {
        if (!(degrees >= 0 && degrees <= MAX_DEGREES)) {
            throw new IllegalArgumentException("the loft must be 0 to " + MAX_DEGREES + " degrees, got " + degrees);
        }
        double ground = Math.hypot(vx, vy);
        double speed = Math.min(ground, maxSpeed);
        if (ground == 0) return new double[]{0, 0, 0};
        if (degrees == 0) {
            // A putt stays exactly the aim (bit for bit as before lofts), only capped to the limit.
            return speed == ground ? new double[]{vx, vy, 0} : new double[]{vx / ground * speed, vy / ground * speed, 0};
        }
        double a = Math.toRadians(degrees);
        double horizontal = speed * Math.cos(a);
        return new double[]{vx / ground * horizontal, vy / ground * horizontal, speed * Math.sin(a)};
    }

    /** The loft of a shot in degrees (0 for a putt). */
    public static double degreesOf(double vx, double vy, double vz) {
        return vz <= 0 ? 0 : Math.toDegrees(Math.atan2(vz, Math.hypot(vx, vy)));
    }

    /** "Putt" or "Chip, 35 degrees up" for the HUD. */
    public static String describe(int degrees) {
        return degrees == 0 ? "Putt" : "Chip, " + degrees + " degrees up";
    }
}
