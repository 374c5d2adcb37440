package minigolf.course;

/**
 * The target. {@code captureSpeed} is only used by the capture rule; null means the default,
 * Penner's free-fall figure for a real cup (1.31 m/s at radius 0.054 m) scaled to this radius.
 */
public record Hole(Vec2 position, double radius, HoleRule rule, Double captureSpeed) {
    public static final double REAL_CUP_RADIUS = 0.054;
    public static final double REAL_CUP_CAPTURE_SPEED = 1.31;

    public double effectiveCaptureSpeed() {
        return captureSpeed != null ? captureSpeed : REAL_CUP_CAPTURE_SPEED * radius / REAL_CUP_RADIUS;
    }
}
