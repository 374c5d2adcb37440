package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * A flying ball's sub-steps: gravity and quadratic drag, a = -g z - k |v| v, integrated with RK4
 * (exact on the parabola without drag) from a start state into (fx, fy, fz, fvx, fvy, fvz), and
 * where within a step it comes down on the ground or the water's surface. {@link BallState} holds the
 * ball's state; this class only integrates.
 */
final class FlightStep {
    /** Bisection halvings when locating the landing inside a step. */
    private static final int LOCATE_ITERATIONS = 50;

    private final Terrain terrain;
    private final double gravity;
    private final double drag;

    private double x, y, z, vx, vy, vz;
    private double ax, ay, azScratch;
    /** The state a sub-step produced. */
    double fx, fy, fz, fvx, fvy, fvz;

    FlightStep(Terrain terrain, double gravity, double drag) {
        this.terrain = terrain;
        this.gravity = gravity;
        this.drag = drag;
    }

    /** Sets the start state of the following sub-steps. */
    void from(double x, double y, double z, double vx, double vy, double vz) {
        this.x = x;
        this.y = y;
        this.z = z;
        this.vx = vx;
        this.vy = vy;
        this.vz = vz;
    }

    /** The surface a flying ball comes down on: the terrain, or the water's surface (z = 0) above it. */
    double groundAt(double px, double py) {
        return Math.max(terrain.height(px, py), 0);
    }

    /** The first sub-step length at which the ball is below the ground, found by bisection. */
    double locateLanding(double tau) {
        double above = 0, below = tau;
        for (int k = 0; k < LOCATE_ITERATIONS; k++) {
            double mid = 0.5 * (above + below);
            advance(mid);
            if (fz < groundAt(fx, fy)) below = mid; else above = mid;
        }
        return below;
    }

    /** RK4 flight sub-step of length tau from the current state into f*: gravity and quadratic drag. */
    void advance(double tau) {
        double half = 0.5 * tau;
        flightAcceleration(vx, vy, vz);
        double k1x = ax, k1y = ay, k1z = azScratch;
        double v2x = vx + half * k1x, v2y = vy + half * k1y, v2z = vz + half * k1z;
        flightAcceleration(v2x, v2y, v2z);
        double k2x = ax, k2y = ay, k2z = azScratch;
        double v3x = vx + half * k2x, v3y = vy + half * k2y, v3z = vz + half * k2z;
        flightAcceleration(v3x, v3y, v3z);
        double k3x = ax, k3y = ay, k3z = azScratch;
        double v4x = vx + tau * k3x, v4y = vy + tau * k3y, v4z = vz + tau * k3z;
        flightAcceleration(v4x, v4y, v4z);
        double sixth = tau / 6;
        fx = x + sixth * (vx + 2 * v2x + 2 * v3x + v4x);
        fy = y + sixth * (vy + 2 * v2y + 2 * v3y + v4y);
        fz = z + sixth * (vz + 2 * v2z + 2 * v3z + v4z);
        fvx = vx + sixth * (k1x + 2 * k2x + 2 * k3x + ax);
        fvy = vy + sixth * (k1y + 2 * k2y + 2 * k3y + ay);
        fvz = vz + sixth * (k1z + 2 * k2z + 2 * k3z + azScratch);
    }

    /** a = -g z - k |v| v. */
    private void flightAcceleration(double ux, double uy, double uz) {
        double k = drag * Math.sqrt(ux * ux + uy * uy + uz * uz);
        ax = -k * ux;
        ay = -k * uy;
        azScratch = -gravity - k * uz;
    }

}
