package minigolf.physics;

/**
 * Trial sub-steps of the rolling equations from the ball's current state, into (nx, ny, nvx, nvy).
 * A rolling step is integrated whole first and again shorter wherever something happens inside it
 * (a zone's edge, a hazard, an obstacle, take-off, the energy running out); only then is it
 * committed. The step the error control chose is held, so it need not be integrated twice.
 */
final class RollingTrial {
    private final BallState ball;
    private final RollingStep rolling;
    /** The RK4 step's error control; null for the other integrators. */
    private final StepControl control;
    /** The end of the last trial. */
    double nx, ny, nvx, nvy;
    // Whether n* hold the controlled step, and its length.
    private boolean held;
    private double heldTau;
    /** The held step's {@link RollingStep#stageBend}. */
    double heldBend;

    RollingTrial(BallState ball, RollingStep rolling, StepControl control) {
        this.ball = ball;
        this.rolling = rolling;
        this.control = control;
    }

    /** A new stroke: nothing held. */
    void reset() {
        held = false;
    }

    /** Whether the steps are error-controlled (RK4). */
    boolean controlled() {
        return control != null;
    }

    /** A sub-step of length tau of the given kind from the ball's state into n*. */
    void run(double tau, RollingStep.Kind kind, double a1x, double a1y) {
        held = false;
        BallState b = ball;
        RollingStep r = rolling;
        r.from(b.x, b.y, b.vx, b.vy, b.hx, b.hy, b.muK, b.fx, b.fy);
        r.advance(tau, kind, a1x, a1y);
        nx = r.nx;
        ny = r.ny;
        nvx = r.nvx;
        nvy = r.nvy;
    }

    /** The step control's length for the coming RK4 step (at most tau); n* then hold that step. */
    double controlledLength(double tau, double a1x, double a1y) {
        BallState b = ball;
        RollingStep r = rolling;
        r.from(b.x, b.y, b.vx, b.vy, b.hx, b.hy, b.muK, b.fx, b.fy);
        double length = control.length(tau, a1x, a1y);
        nx = r.nx;
        ny = r.ny;
        nvx = r.nvx;
        nvy = r.nvy;
        held = true;
        heldTau = length;
        heldBend = r.stageBend;
        return length;
    }

    /** Whether n* already hold the integrator's step of length tau (the controlled one). */
    boolean holds(double tau) {
        return held && tau == heldTau;
    }
}
