package minigolf.collision;

/**
 * Exact time of impact of a sphere of radius r whose centre moves from p to p + d (t in [0, 1])
 * against a plane face, a segment (the capsule round it) and a point. Each returns the first t at
 * which the sphere touches while approaching, or +infinity; the caller keeps the smallest.
 * A sphere already touching (within rounding) and moving closer is a hit at t = 0; one moving away
 * or along is not, so a ball sliding along a wall never sticks to it.
 */
final class SweepTests {
    /** Motion into a feature slower than this share of the sweep length counts as moving along it. */
    static final double ALONG = 1e-9;

    private SweepTests() {
    }

    /**
     * t at which the sphere touches the point (qx, qy, qz): |p + t d - q| = r. Writes the normal
     * into out[0..2] on a hit.
     */
    static double point(double px, double py, double pz, double dx, double dy, double dz, double r,
                        double qx, double qy, double qz, double limit, double[] out) {
        double mx = px - qx, my = py - qy, mz = pz - qz;
        double a = dx * dx + dy * dy + dz * dz;
        double b = mx * dx + my * dy + mz * dz;
        double c = mx * mx + my * my + mz * mz - r * r;
        double t = firstRoot(a, b, c, Math.sqrt(a));
        if (!(t < limit)) return Double.POSITIVE_INFINITY;
        double cx = mx + t * dx, cy = my + t * dy, cz = mz + t * dz;
        return normal(cx, cy, cz, t, out);
    }

    /** t at which the sphere touches the segment a-b (the side of the capsule; the ends are points). */
    static double segment(double px, double py, double pz, double dx, double dy, double dz, double r,
                          double ax, double ay, double az, double bx, double by, double bz, double limit, double[] out) {
        double ex = bx - ax, ey = by - ay, ez = bz - az;
        double mx = px - ax, my = py - ay, mz = pz - az;
        double ee = ex * ex + ey * ey + ez * ez;
        if (ee == 0) return Double.POSITIVE_INFINITY;
        double ed = ex * dx + ey * dy + ez * dz, em = ex * mx + ey * my + ez * mz;
        double dd = dx * dx + dy * dy + dz * dz, md = mx * dx + my * dy + mz * dz;
        double mm = mx * mx + my * my + mz * mz;
        double a = dd - ed * ed / ee;
        double b = md - em * ed / ee;
        double c = mm - em * em / ee - r * r;
        double t = firstRoot(a, b, c, Math.sqrt(dd));
        if (!(t < limit)) return Double.POSITIVE_INFINITY;
        double s = (em + t * ed) / ee;
        if (s < 0 || s > 1) return Double.POSITIVE_INFINITY;
        double cx = mx + t * dx - s * ex, cy = my + t * dy - s * ey, cz = mz + t * dz - s * ez;
        return normal(cx, cy, cz, t, out);
    }

    /**
     * The smallest t in [0, 1] with a t^2 + 2 b t + c = 0 on the way in (the distance falling
     * through r), or +infinity. c &lt;= 0 means touching at the start: a hit at 0 if approaching.
     */
    private static double firstRoot(double a, double b, double c, double length) {
        if (b >= -ALONG * length * length) return Double.POSITIVE_INFINITY; // moving away or along
        if (c <= 0) return 0;
        if (a <= 0) return Double.POSITIVE_INFINITY;
        double disc = b * b - a * c;
        if (disc < 0) return Double.POSITIVE_INFINITY;
        double t = c / (-b + Math.sqrt(disc)); // = (-b - sqrt(disc)) / a, without cancellation
        return t <= 1 ? t : Double.POSITIVE_INFINITY;
    }

    private static double normal(double cx, double cy, double cz, double t, double[] out) {
        double length = Math.sqrt(cx * cx + cy * cy + cz * cz);
        if (length == 0) return Double.POSITIVE_INFINITY;
        out[0] = cx / length;
        out[1] = cy / length;
        out[2] = cz / length;
        return t;
    }
}
