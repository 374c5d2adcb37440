package minigolf.physics;

/**
 * The integrator's mutable state, which every piece of a {@link Stroke} reads and rewrites: the
 * ball (position, velocity, time and the terrain sample under it), the start of the last rolling
 * step (the energy guard measures the step from there and may go back to it), the flags by which a
 * piece of a step asks for the rest of the step, and the outcome once the stroke has ended. Plain
 * fields, as the pieces use them on the hot path; one object per stroke, never shared.
 */
final class BallState {
    private final GroundCache ground;
    private final FrictionField friction;
    /** Push zones and magnets; null without them. */
    private final ForceField forces;
    private final double gravity;
    private final boolean complete;
    private final double[] sample = new double[3];

    /** Where the stroke began (a ball a moving obstacle crushes or catches is put back there). */
    double startX, startY;
    /** The ground's height where the stroke began. */
    double startZ;

    // The ball and the terrain sample at it (reused as the first stage of the next step).
    double x, y, vx, vy, t;
    double h, hx, hy, muK;
    /**
     * The force of push zones and magnets at the ball (m/s², 0 without them), and the pull gradient
     * the rules of rest see (ForceField.pullGradient; the ground's gradient without forces).
     */
    double fx, fy, pullX, pullY;
    int steps;
    // The third dimension: z is the contact point's height (h while rolling), vz its rate of change in flight.
    double z, vz;
    boolean flying;

    // The state at the start of the last committed rolling step.
    double px, py, pvx, pvy, pt, ph, phx, phy, pMuK, pfx, pfy, pPullX, pPullY;

    /** Set by a piece of a step (a contact, a launch, a landing) when the rest of the step is to be integrated. */
    boolean resume;
    /** Set when the piece was one the error control shortened: no contact, so it does not count towards a wedge. */
    boolean subPiece;
    /** Set when the ball meets a moving obstacle within the current step (a wedge there crushes it). */
    boolean movingContact;
    /** Contacts with moving obstacles in this stroke (too many and the ball is caught: out). */
    int movingContacts;
    /** The time the current piece took. */
    double pieceTime;

    /** Null while the stroke runs; then how it ended, and where. */
    Outcome outcome;
    double endX, endY, endZ;

    BallState(GroundCache ground, FrictionField friction, ForceField forces, double gravity, boolean complete) {
        this.ground = ground;
        this.friction = friction;
        this.forces = forces;
        this.gravity = gravity;
        this.complete = complete;
    }

    /** A new stroke: the ball at (x, y) with velocity (vx, vy) on the ground, everything else cleared. */
    void reset(double x, double y, double vx, double vy) {
        this.x = x;
        this.y = y;
        this.vx = vx;
        this.vy = vy;
        startX = x;
        startY = y;
        startZ = 0;
        t = 0;
        h = hx = hy = muK = 0;
        fx = fy = pullX = pullY = 0;
        steps = 0;
        z = vz = 0;
        flying = false;
        px = py = pvx = pvy = pt = ph = phx = phy = pMuK = 0;
        pfx = pfy = pPullX = pPullY = 0;
        resume = false;
        subPiece = false;
        movingContact = false;
        movingContacts = 0;
        pieceTime = 0;
        outcome = null;
        endX = endY = endZ = 0;
    }

    /** Whether a ball coming to rest here ends the stroke in a hazard zone. */
    boolean restsInHazard() {
        return friction.restsInHazard(x, y);
    }

    /** Whether the ball's centre here is in a hazard zone it may not enter. */
    boolean entersHazard() {
        return friction.entersHazard(x, y);
    }

    /** Samples the terrain, friction and forces under the ball into h, hx, hy, muK, fx, fy, pullX, pullY. */
    void sampleGround() {
        double[] g = ground.at(x, y);
        h = g[0];
        hx = g[1];
        hy = g[2];
        if (!Double.isFinite(h + hx + hy)) throw NonFiniteMotionException.terrain(x, y);
        muK = friction.kinetic(x, y);
        if (forces == null) {
            pullX = hx;
            pullY = hy;
            return;
        }
        forces.force(x, y, sample);
        fx = sample[0];
        fy = sample[1];
        ForceField.pullGradient(hx, hy, fx, fy, gravity, complete, sample);
        pullX = sample[0];
        pullY = sample[1];
    }

    /** Vertical velocity: in flight its own, while rolling the rate at which the ground under the ball rises. */
    double verticalSpeed() {
        return flying ? vz : hx * vx + hy * vy;
    }

    /** Remembers the current state as the start of the rolling step about to be committed. */
    void markStepStart() {
        px = x;
        py = y;
        pvx = vx;
        pvy = vy;
        pt = t;
        ph = h;
        phx = hx;
        phy = hy;
        pMuK = muK;
        pfx = fx;
        pfy = fy;
        pPullX = pullX;
        pPullY = pullY;
    }

    /** Goes back to the start of the last committed rolling step. */
    void backToStepStart() {
        x = px;
        y = py;
        vx = pvx;
        vy = pvy;
        h = ph;
        hx = phx;
        hy = phy;
        muK = pMuK;
        fx = pfx;
        fy = pfy;
        pullX = pPullX;
        pullY = pPullY;
        t = pt;
    }

    /** Ends the stroke: the outcome, the end point, and the ball still. */
    void end(Outcome result, double ex, double ey, double ez) {
        outcome = result;
        endX = ex;
        endY = ey;
        endZ = ez;
        vx = 0;
        vy = 0;
        vz = 0;
        flying = false;
    }
}
