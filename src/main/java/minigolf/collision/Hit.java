package minigolf.collision;

/** The first contact of a swept sphere: where along the sweep, the contact normal and what was hit. Mutable scratch. */
public final class Hit {
    /** Fraction of the sweep, in [0, 1], at which the sphere first touches. */
    public double fraction;
    /** Unit normal of the contact, pointing from the obstacle towards the ball's centre. */
    public double nx, ny, nz;
    public double restitution;
    /** Index of the obstacle in the course's list. */
    public int obstacle;
}
