package minigolf.course;

/** The course's physical constants (course file field {@code physics}). */
public record PhysicsSettings(double gravity, double kineticFriction, double staticFriction,
                              double maxSpeed, PhysicsModel model) {
    public static final double DEFAULT_GRAVITY = 9.81;
    public static final double DEFAULT_MAX_SPEED = 5.0;

    public PhysicsSettings withModel(PhysicsModel newModel) {
        return new PhysicsSettings(gravity, kineticFriction, staticFriction, maxSpeed, newModel);
    }
}
