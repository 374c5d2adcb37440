package minigolf.bot;

/**
 * A shot: the ball's initial velocity in m/s, and the wait (s, {@code waitSeconds}; the JSON of
 * {@code solve} and {@code experiment} calls it {@code "wait"}) before it is played. {@code vz} is 0
 * for a putt along the ground; a positive {@code vz} is a chip (the engine's 3-component shot,
 * docs/physics.md). The speed limit applies to the whole vector. The wait matters only where
 * obstacles move (docs/course-format.md, "Moving obstacles"): the shot is played that many seconds
 * of the course clock after the bot was asked.
 */
public record Shot(double vx, double vy, double vz, double waitSeconds) {
    public Shot {
        if (!Double.isFinite(vx) || !Double.isFinite(vy) || !Double.isFinite(vz)) {
            throw new IllegalArgumentException("shot velocity must be finite, got " + vx + ", " + vy + ", " + vz);
        }
        if (!(waitSeconds >= 0) || !Double.isFinite(waitSeconds)) {
            throw new IllegalArgumentException("the wait must be >= 0 s, got " + waitSeconds);
        }
    }

    /** A shot played at once. */
    public Shot(double vx, double vy, double vz) {
        this(vx, vy, vz, 0);
    }

    /** The same velocity, played after {@code seconds}. */
    public Shot withWait(double seconds) {
        return new Shot(vx, vy, vz, seconds);
    }

    /** A putt along the ground. */
    public static Shot of(double vx, double vy) {
        return new Shot(vx, vy, 0);
    }

    /** A putt in direction {@code angle} (radians, from +x towards +y) at {@code speed}. */
    public static Shot polar(double angle, double speed) {
        return of(speed * Math.cos(angle), speed * Math.sin(angle));
    }

    public double speed() {
        return Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    public boolean isPutt() {
        return vz == 0;
    }

    /** This shot scaled down (same direction) so that its speed is at most {@code maxSpeed}. */
    public Shot limitedTo(double maxSpeed) {
        double s = speed();
        if (s <= maxSpeed) return this;
        double k = maxSpeed / s;
        return new Shot(vx * k, vy * k, vz * k, waitSeconds);
    }
}
