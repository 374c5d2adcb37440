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
    /** The velocity of the obstacle's surface at the contact (m/s): 0 for a still obstacle, set for a moving one. */
    public double ux, uy, uz;
    /** Index of the breakable brick hit in the course's {@code bricks}, or -1 for any other obstacle. */
    public int brick = -1;
    /** Whether the obstacle hit moves (then {@link #ux}, {@link #uy}, {@link #uz} hold its velocity there). */
    public boolean moving;

    /** A contact with a still obstacle. */
    public void still(double fraction, double nx, double ny, double nz, double restitution, int obstacle) {
        this.fraction = fraction;
        this.nx = nx;
        this.ny = ny;
        this.nz = nz;
        this.restitution = restitution;
        this.obstacle = obstacle;
        brick = -1;
        ux = 0;
        uy = 0;
        uz = 0;
        moving = false;
    }

    /** Copies another contact into this one. */
    public void set(Hit other) {
        fraction = other.fraction;
        nx = other.nx;
        ny = other.ny;
        nz = other.nz;
        restitution = other.restitution;
        obstacle = other.obstacle;
        brick = other.brick;
        ux = other.ux;
        uy = other.uy;
        uz = other.uz;
        moving = other.moving;
    }
}
