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

    // The ball and the terrain sample at it (reused as the first stage of the next step).
    double x, y, vx, vy, t;
    double h, hx, hy, muK;
    int steps;
    // The third dimension: z is the contact point's height (h while rolling), vz its rate of change in flight.
    double z, vz;
    boolean flying;

    // The state at the start of the last committed rolling step.
    double px, py, pvx, pvy, pt, ph, phx, phy, pMuK;

    /** Set by a piece of a step (a contact, a launch, a landing) when the rest of the step is to be integrated. */
    boolean resume;
    /** Set when the piece was one the error control shortened: no contact, so it does not count towards a wedge. */
    boolean subPiece;
    /** The time the current piece took. */
    double pieceTime;

    /** Null while the stroke runs; then how it ended, and where. */
    Outcome outcome;
    double endX, endY, endZ;

    BallState(GroundCache ground, FrictionField friction) {
        this.ground = ground;
        this.friction = friction;
    }

    /** A new stroke: the ball at (x, y) with velocity (vx, vy) on the ground, everything else cleared. */
    void reset(double x, double y, double vx, double vy) {
        this.x = x;
        this.y = y;
        this.vx = vx;
        this.vy = vy;
        t = 0;
        h = hx = hy = muK = 0;
        steps = 0;
        z = vz = 0;
        flying = false;
        px = py = pvx = pvy = pt = ph = phx = phy = pMuK = 0;
        resume = false;
        subPiece = false;
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

    /** Samples the terrain and friction under the ball into h, hx, hy, muK. */
    void sampleGround() {
        double[] sample = ground.at(x, y);
        h = sample[0];
        hx = sample[1];
        hy = sample[2];
        if (!Double.isFinite(h + hx + hy)) throw NonFiniteMotionException.terrain(x, y);
        muK = friction.kinetic(x, y);
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
