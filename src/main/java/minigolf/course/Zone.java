package minigolf.course;

/** An area with its own friction (sand, a fast strip). Later zones in the file win over earlier ones. */
public record Zone(Shape shape, double kineticFriction, double staticFriction) {
}
