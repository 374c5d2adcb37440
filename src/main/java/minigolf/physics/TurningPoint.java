package minigolf.physics;

/**
 * How slow a ball rolling up a uniform slope steeper than kinetic friction gets as it turns round
 * (classic model, docs/physics.md). With s = |grad h|, k = mu/s &lt; 1, psi the angle between the
 * velocity and the downhill direction and T = tan(psi/2), the speed along the path is
 * V = C (T^(k-1) + T^(k+1)) and psi only decreases, so the speed is lowest at
 * T*^2 = (1-k)/(1+k).
 */
final class TurningPoint {
    private TurningPoint() {
    }

    /**
     * The lowest speed still ahead (m/s) of a ball at velocity (vx, vy) on slope (hx, hy) with
     * friction mu &lt; |grad h|; the current speed once the minimum is behind it.
     */
    static double minimumSpeed(double vx, double vy, double hx, double hy, double mu) {
        double speed = Math.sqrt(vx * vx + vy * vy);
        double s = Math.sqrt(hx * hx + hy * hy);
        double k = mu / s;
        double cos = -(vx * hx + vy * hy) / (speed * s);
        double sin = Math.abs(vx * hy - vy * hx) / (speed * s);
        if (sin == 0) return cos < 0 ? 0 : speed;
        double t = (1 - cos) / sin;
        double tStar = Math.sqrt((1 - k) / (1 + k));
        if (t <= tStar) return speed;
        double atStar = Math.pow(tStar, k - 1) + Math.pow(tStar, k + 1);
        // T^(k-1) + T^(k+1) = T^(k+1) (1 + T^-2), in logarithms so a heading a hair off straight up never overflows.
        double logNow = (k + 1) * Math.log(t) + Math.log1p(1 / (t * t));
        return speed * atStar * Math.exp(-logNow);
    }
}
