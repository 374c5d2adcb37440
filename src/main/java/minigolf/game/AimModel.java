package minigolf.game;

/**
 * Turns a drag on the ground into a shot. The player presses on the ball and pulls back, like a
 * slingshot: the ball goes the opposite way to the pull, and the speed grows with the pull's
 * length, {@code speed = maxSpeed * min(1, pull / fullPull)}; the maximum speed always holds.
 */
public final class AimModel {
    /** A pull of this many metres on the ground gives full power. */
    public static final double DEFAULT_FULL_PULL = 2.0;

    private AimModel() {
    }

    /** The velocity for a pull from the ball (bx, by) to the ground point (px, py). */
    public static double[] velocityForPull(double bx, double by, double px, double py, double maxSpeed, double fullPull) {
        double dx = bx - px, dy = by - py;
        double pull = Math.hypot(dx, dy);
        if (pull < 1e-9) return new double[]{0, 0};
        double speed = maxSpeed * Math.min(1, pull / fullPull);
        return new double[]{dx / pull * speed, dy / pull * speed};
    }

    /**
     * A typed velocity checked against the maximum speed.
     *
     * @return null if it is acceptable, else the one-line reason
     */
    public static String checkTyped(double vx, double vy, double maxSpeed) {
        return checkTyped(vx, vy, 0, maxSpeed);
    }

    /** As {@link #checkTyped(double, double, double)} for a chip: vz &gt;= 0, the limit on the whole vector. */
    public static String checkTyped(double vx, double vy, double vz, double maxSpeed) {
        if (!Double.isFinite(vx) || !Double.isFinite(vy) || !Double.isFinite(vz)) return "the velocity must be numbers";
        if (vz < 0) return "vz must be 0 or more (the ball cannot be hit into the ground)";
        double speed = Math.sqrt(vx * vx + vy * vy + vz * vz);
        if (speed == 0) return "the velocity is zero";
        if (speed > maxSpeed * (1 + 1e-12)) {
            return String.format(java.util.Locale.ROOT, "%.3f m/s is faster than the course's maximum %.3f m/s", speed, maxSpeed);
        }
        return null;
    }
}
