package minigolf.course;

/** A point in space, in metres; z is up. */
public record Vec3(double x, double y, double z) {
}
