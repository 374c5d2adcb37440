package minigolf.course;

/** Plane geometry of points and line segments, shared by the bots' maps and the renderer's shore cells. */
public final class Segments {
    private Segments() {
    }

    /**
     * Twice the signed area of the triangle (a, b, p): positive when p lies to the left of the line
     * from a to b, negative to its right, 0 on it.
     */
    public static double side(double ax, double ay, double bx, double by, double px, double py) {
        return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    }

    /** The distance from the point p to the segment from a to b (to a itself when the segment has no length). */
    public static double distance(double px, double py, double ax, double ay, double bx, double by) {
        double vx = bx - ax, vy = by - ay, len2 = vx * vx + vy * vy;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * vx + (py - ay) * vy) / len2));
        return Math.hypot(px - ax - t * vx, py - ay - t * vy);
    }
}
