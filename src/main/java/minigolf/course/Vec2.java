package minigolf.course;

/** A point or vector in the course plane, in metres. */
public record Vec2(double x, double y) {
    public double distanceTo(Vec2 other) {
        return Math.hypot(x - other.x, y - other.y);
    }
}
