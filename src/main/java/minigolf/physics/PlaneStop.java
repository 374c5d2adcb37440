package minigolf.physics;

/**
 * Where and when a ball rolling on a uniform slope shallower than kinetic friction stops, in closed
 * form (classic model; docs/physics.md, "The stopping tail"). With s = |grad h| &lt; mu, psi the angle
 * between the velocity and the downhill direction, V the speed and T = tan(psi/2), the path obeys
 * V = C T^(k-1) (1 + T^2), k = mu/s (as in {@link TurningPoint}), and dt = -V dT / (g s T); both
 * displacements and the time integrate in powers of T, and at the stop (T = 0) they are, with
 * c = cos^2(psi/2) and q = sin^2(psi/2) at the start,
 * <pre>
 *   downhill  V^2 (c^2 / (2g (mu - s)) - q^2 / (2g (mu + s)))
 *   across    V^2 sin(psi) (c / (g (2mu - s)) + q / (g (2mu + s)))
 *   time      V (c / (g (mu - s)) + q / (g (mu + s)))
 *   path      V^2 (c^2 / (2g (mu - s)) + q c / (g mu) + q^2 / (2g (mu + s)))
 * </pre>
 * (the path's length: the integral of V dt = -V^2 dT / (g s T)).
 * (on level ground: straight on, V^2 / (2 mu g) in V / (mu g)). The heading near the stop goes like
 * (t_stop - t)^(1/(k-1)), which a step-by-step integrator follows only in tiny steps.
 */
final class PlaneStop {
    /** The displacement to the stop (m), the time it takes (s) and the length of its path (m), from the last {@link #solve}. */
    double dx, dy, time, path;

    /**
     * Solves for a ball at velocity (vx, vy), not zero, on the plane of gradient (gx, gy) with
     * kinetic friction mu greater than the slope, under gravity g.
     */
    void solve(double vx, double vy, double gx, double gy, double mu, double g) {
        double speedSquared = vx * vx + vy * vy;
        double speed = Math.sqrt(speedSquared);
        double s = Math.sqrt(gx * gx + gy * gy);
        // The downhill direction; on level ground the ball runs straight on (psi = 0).
        double ux = s > 0 ? -gx / s : vx / speed, uy = s > 0 ? -gy / s : vy / speed;
        double along = vx * ux + vy * uy;
        double cos = Math.max(-1, Math.min(1, along / speed));
        double c = 0.5 * (1 + cos), q = 0.5 * (1 - cos);
        // The velocity across the fall line: V sin(psi) times the unit vector the ball drifts along.
        double px = vx - along * ux, py = vy - along * uy;
        double down = speedSquared * (c * c / (2 * g * (mu - s)) - q * q / (2 * g * (mu + s)));
        double across = speed * (c / (g * (2 * mu - s)) + q / (g * (2 * mu + s)));
        dx = down * ux + across * px;
        dy = down * uy + across * py;
        time = speed * (c / (g * (mu - s)) + q / (g * (mu + s)));
        path = speedSquared * (c * c / (2 * g * (mu - s)) + q * c / (g * mu) + q * q / (2 * g * (mu + s)));
    }
}
