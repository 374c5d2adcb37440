package minigolf.physics;

/**
 * A flying ball meeting the ground (docs/physics.md, "Flight"): normal speed times the
 * restitution e (the course's groundRestitution or Penner's turf model), tangential speed reduced
 * by Coulomb impact friction (at most to 5/7, where the ball rolls). A bounce lower than a 1 mm
 * hop settles the ball into rolling. {@link FlightPhase} applies the result.
 */
final class GroundImpact {
    /** Coulomb friction of a landing ball on turf; the tangential loss is at most 2/7 (the ball then rolls). */
    static final double IMPACT_FRICTION = 0.4;

    private final Double groundRestitution;
    private final double hopSpeed;
    /** The velocity after the impact. */
    double vx, vy, vz;
    /** Whether the ball settles into rolling (then vz is 0 and (vx, vy) its rolling velocity). */
    boolean settles;
    /** The speed before and after, for the event. */
    double before, after;

    GroundImpact(Double groundRestitution, double hopSpeed) {
        this.groundRestitution = groundRestitution;
        this.hopSpeed = hopSpeed;
    }

    /** A ball at velocity (ux, uy, uz) meets ground of slope (hx, hy). */
    void impact(double ux, double uy, double uz, double hx, double hy) {
        double norm = Math.sqrt(1 + hx * hx + hy * hy);
        double gx = -hx / norm, gy = -hy / norm, gz = 1 / norm;
        before = Math.sqrt(ux * ux + uy * uy + uz * uz);
        double vn = -(ux * gx + uy * gy + uz * gz); // speed into the ground
        if (vn < 0) vn = 0;
        double e = groundRestitution != null ? groundRestitution : pennerRestitution(vn);
        double tx = ux + vn * gx, ty = uy + vn * gy, tz = uz + vn * gz;
        double tangential = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (tangential > 0) {
            double loss = Math.min(IMPACT_FRICTION * (1 + e) * vn, 2.0 / 7.0 * tangential);
            double keep = 1 - loss / tangential;
            tx *= keep;
            ty *= keep;
            tz *= keep;
        }
        double up = e * vn;
        settles = up < hopSpeed;
        if (settles) {
            vx = tx;
            vy = ty;
            vz = 0;
            after = Math.sqrt(tx * tx + ty * ty + tz * tz);
        } else {
            vx = tx + up * gx;
            vy = ty + up * gy;
            vz = tz + up * gz;
            after = Math.sqrt(vx * vx + vy * vy + vz * vz);
        }
    }

    /** Penner's turf restitution e = 0.510 - 0.0375 vn + 0.000903 vn^2 (fitted for vn up to 20 m/s), kept in [0, 1]. */
    static double pennerRestitution(double vn) {
        double v = Math.min(vn, 20);
        return Math.max(0, Math.min(1, 0.510 - 0.0375 * v + 0.000903 * v * v));
    }
}
