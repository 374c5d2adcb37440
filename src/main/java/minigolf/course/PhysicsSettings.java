package minigolf.course;

/**
 * The course's physical constants (course file field {@code physics}).
 *
 * @param ballRadius        m; the collision sphere's radius (the ball's contact point is its lowest point)
 * @param ballMass          kg; with the radius it sets how strongly air drag slows a flying ball
 * @param dragCoefficient   Cd of the flying ball (0 = no air drag: exact parabolas)
 * @param airDensity        kg/m^3
 * @param groundRestitution the normal restitution of a landing ball, or null for Penner's turf
 *                          model e = 0.510 - 0.0375 vn + 0.000903 vn^2
 * @param puttsOnly         the ball is only ever struck along the ground: a shot's upward part is
 *                          dropped (a classic track: the original game had no chips)
 */
public record PhysicsSettings(double gravity, double kineticFriction, double staticFriction,
                              double maxSpeed, PhysicsModel model, double ballRadius, double ballMass,
                              double dragCoefficient, double airDensity, Double groundRestitution, boolean puttsOnly) {
    public static final double DEFAULT_GRAVITY = 9.81;
    public static final double DEFAULT_MAX_SPEED = 5.0;
    /** A golf ball: 42.67 mm across, 45.93 g. */
    public static final double DEFAULT_BALL_RADIUS = 0.02135;
    public static final double DEFAULT_BALL_MASS = 0.04593;
    /** A golf ball's drag coefficient below Reynolds number 5e4 (every putting and chipping speed). */
    public static final double DEFAULT_DRAG_COEFFICIENT = 0.5;
    public static final double DEFAULT_AIR_DENSITY = 1.2;

    /** Settings where chips may be played (every course but those that say {@code puttsOnly}). */
    public PhysicsSettings(double gravity, double kineticFriction, double staticFriction, double maxSpeed,
                           PhysicsModel model, double ballRadius, double ballMass, double dragCoefficient,
                           double airDensity, Double groundRestitution) {
        this(gravity, kineticFriction, staticFriction, maxSpeed, model, ballRadius, ballMass, dragCoefficient,
                airDensity, groundRestitution, false);
    }

    /** The settings of a course file without the ball and flight fields: those take their defaults. */
    public PhysicsSettings(double gravity, double kineticFriction, double staticFriction, double maxSpeed,
                           PhysicsModel model) {
        this(gravity, kineticFriction, staticFriction, maxSpeed, model, DEFAULT_BALL_RADIUS, DEFAULT_BALL_MASS,
                DEFAULT_DRAG_COEFFICIENT, DEFAULT_AIR_DENSITY, null);
    }

    public PhysicsSettings withModel(PhysicsModel newModel) {
        return new PhysicsSettings(gravity, kineticFriction, staticFriction, maxSpeed, newModel, ballRadius, ballMass,
                dragCoefficient, airDensity, groundRestitution, puttsOnly);
    }

    public PhysicsSettings withFlight(double newDragCoefficient, Double newGroundRestitution) {
        return new PhysicsSettings(gravity, kineticFriction, staticFriction, maxSpeed, model, ballRadius, ballMass,
                newDragCoefficient, airDensity, newGroundRestitution, puttsOnly);
    }

    /** These settings with {@code puttsOnly} set as given. */
    public PhysicsSettings withPuttsOnly(boolean newPuttsOnly) {
        return new PhysicsSettings(gravity, kineticFriction, staticFriction, maxSpeed, model, ballRadius, ballMass,
                dragCoefficient, airDensity, groundRestitution, newPuttsOnly);
    }

    /** k in the drag acceleration -k |v| v: Cd rho A / (2 m), A the ball's cross-section. */
    public double dragFactor() {
        return dragCoefficient * airDensity * Math.PI * ballRadius * ballRadius / (2 * ballMass);
    }
}
