package minigolf.physics;

/**
 * Where a step's cubic path crosses a rectangular push zone's edge, in closed form: the roots of
 * the cubic x(s) = c and y(s) = c for each edge coordinate c, found by Newton's method on the
 * cubic's monotone pieces. {@link StepLocator} bisects the step's cubic for the first point in
 * another push region; with the crossings known, the test at each halving point is known too,
 * except within a hair of a crossing (where floating-point rounding decides), so only a few points
 * are tested for real instead of 33 ({@link #bisect}). The answer is the bisection's own, bit for
 * bit: the same halvings, each decided as the test would decide it.
 *
 * <p>Used only where every push zone is a rectangle and there are no friction zones (then the
 * region at a point changes only at those coordinates); otherwise, and wherever a crossing is not
 * clean (the path grazes an edge, or runs almost along it), the caller bisects as before.
 */
final class EdgeCrossings {
    /** The edge coordinates of the push zones: x = xEdges[k], y = yEdges[k]. */
    private final double[] xEdges, yEdges;
    /** The crossings found on the current cubic: a guard [lo, hi] round each, in which the test is asked. */
    private final double[] guardLo, guardHi;
    private int guards;
    /** The test's value in each gap between guards (0 unknown, 1 true, -1 false). */
    private final byte[] gapValue;
    /**
     * A crossing whose guard (the parameter range in which rounding may put a point either side of
     * the edge) is wider than this is not clean: the caller bisects as before.
     */
    static final double WIDEST_GUARD = 1e-6;

    private EdgeCrossings(double[] xEdges, double[] yEdges) {
        this.xEdges = xEdges;
        this.yEdges = yEdges;
        int most = 3 * (xEdges.length + yEdges.length);
        guardLo = new double[most];
        guardHi = new double[most];
        gapValue = new byte[most + 1];
    }

    /** The crossings of these forces' push zones, or null where they do not decide the region alone. */
    static EdgeCrossings of(FrictionField friction, ForceField forces) {
        if (friction.hasZones() || forces == null || !forces.hasPushZones()) return null;
        double[] boxes = forces.pushRectangles();
        if (boxes == null) return null;
        int n = boxes.length / 4;
        double[] xs = new double[2 * n], ys = new double[2 * n];
        for (int k = 0; k < n; k++) {
            xs[2 * k] = boxes[4 * k];
            xs[2 * k + 1] = boxes[4 * k + 2];
            ys[2 * k] = boxes[4 * k + 1];
            ys[2 * k + 1] = boxes[4 * k + 3];
        }
        return new EdgeCrossings(xs, ys);
    }

    /**
     * As StepLocator's bisection on the cubic from (x0, y0) with tangent (mx0, my0) to (x1, y1)
     * with tangent (mx1, my1): the first point found that passes the test (which holds at the
     * end), halving [0, 1] while wider than {@code close}, at most {@code iterations} times. NaN
     * where a crossing is not clean: then the caller bisects.
     */
    double bisect(double x0, double mx0, double x1, double mx1, double y0, double my0, double y1, double my1,
                  StepLocator.PointTest test, double close, int iterations) {
        guards = 0;
        if (!crossings(x0, mx0, x1, mx1, xEdges) || !crossings(y0, my0, y1, my1, yEdges)) return Double.NaN;
        java.util.Arrays.fill(gapValue, 0, guards + 1, (byte) 0);
        double before = 0, after = 1;
        for (int k = 0; k < iterations && after - before > close; k++) {
            double mid = 0.5 * (before + after);
            if (passes(mid, test, x0, mx0, x1, mx1, y0, my0, y1, my1)) after = mid; else before = mid;
        }
        return after;
    }

    /** The test at s: asked within a guard, else the value of the gap s lies in (asked once a gap). */
    private boolean passes(double s, StepLocator.PointTest test, double x0, double mx0, double x1, double mx1,
                           double y0, double my0, double y1, double my1) {
        int gap = 0;
        for (int g = 0; g < guards; g++) {
            if (s >= guardLo[g] && s <= guardHi[g]) {
                return test.at(PathSweep.hermite(s, x0, mx0, x1, mx1), PathSweep.hermite(s, y0, my0, y1, my1));
            }
            if (guardHi[g] < s) gap++;
        }
        if (gapValue[gap] == 0) {
            boolean value = test.at(PathSweep.hermite(s, x0, mx0, x1, mx1), PathSweep.hermite(s, y0, my0, y1, my1));
            gapValue[gap] = (byte) (value ? 1 : -1);
        }
        return gapValue[gap] > 0;
    }

    /**
     * Adds a guard round every s in [0, 1] where the cubic p(s) (ends p0, p1, tangents m0, m1)
     * crosses one of the coordinates; false where one is not clean (it grazes a coordinate, or
     * crosses it too flatly, or within rounding of the ends).
     */
    private boolean crossings(double p0, double m0, double p1, double m1, double[] edges) {
        // p(s) = a3 s^3 + a2 s^2 + m0 s + p0; p'(s) = 3 a3 s^2 + 2 a2 s + m0.
        double a2 = -3 * p0 - 2 * m0 + 3 * p1 - m1, a3 = 2 * p0 + m0 - 2 * p1 + m1;
        // Rounding of PathSweep.hermite at this scale (a generous bound on a few ulps of its terms).
        double rounding = 64 * Math.ulp(Math.abs(p0) + Math.abs(m0) + Math.abs(p1) + Math.abs(m1));
        // The cubic lies within the hull of its Bezier points.
        double c1 = p0 + m0 / 3, c2 = p1 - m1 / 3;
        double lo = Math.min(Math.min(p0, p1), Math.min(c1, c2)) - rounding;
        double hi = Math.max(Math.max(p0, p1), Math.max(c1, c2)) + rounding;
        // Its monotone pieces: [0, 1] split where p' = 0.
        double s1 = Double.NaN, s2 = Double.NaN;
        double qa = 3 * a3, qb = 2 * a2, qc = m0;
        if (qa != 0) {
            double disc = qb * qb - 4 * qa * qc;
            if (disc >= 0) {
                double root = Math.sqrt(disc);
                double q = -0.5 * (qb + Math.copySign(root, qb));
                double r1 = q / qa, r2 = q != 0 ? qc / q : r1;
                s1 = Math.min(r1, r2);
                s2 = Math.max(r1, r2);
            }
        } else if (qb != 0) {
            s1 = -qc / qb;
        }
        for (double c : edges) {
            if (c < lo || c > hi) continue;
            double a = 0, fa = PathSweep.hermite(0, p0, m0, p1, m1) - c;
            if (Math.abs(fa) <= 4 * rounding) return false;
            for (int piece = 0; piece < 3; piece++) {
                double b = piece == 0 ? s1 : piece == 1 ? s2 : 1;
                if (!(b > a && b <= 1)) continue;
                double fb = PathSweep.hermite(b, p0, m0, p1, m1) - c;
                // A turn (or the end) within rounding of the edge: the path grazes it.
                if (Math.abs(fb) <= 4 * rounding) return false;
                if ((fa < 0) != (fb < 0) && !root(p0, m0, p1, m1, c, a, fa, b, rounding)) return false;
                a = b;
                fa = fb;
            }
        }
        return true;
    }

    /** The crossing of c on the monotone piece [a, b] (fa, fb of opposite signs), by safeguarded Newton; its guard added. */
    private boolean root(double p0, double m0, double p1, double m1, double c, double a, double fa, double b,
                         double rounding) {
        double s = a + (b - a) * fa / (fa - PathSweep.hermite(b, p0, m0, p1, m1) + c);
        double lo = a, hi = b;
        boolean rising = fa < 0;
        for (int k = 0; k < 60; k++) {
            double f = PathSweep.hermite(s, p0, m0, p1, m1) - c;
            if (Math.abs(f) <= rounding) break;
            if ((f < 0) == rising) lo = s; else hi = s;
            double next = s - f / slope(s, p0, m0, p1, m1);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (next == s || k == 59) return false;
            s = next;
        }
        double d = Math.abs(slope(s, p0, m0, p1, m1));
        // Within `rounding` of c the computed point may fall either side; s itself is within that of the crossing.
        double guard = 4 * rounding / d;
        if (!(guard < WIDEST_GUARD)) return false;
        guardLo[guards] = s - guard;
        guardHi[guards] = s + guard;
        guards++;
        return true;
    }

    /** The cubic's derivative at s. */
    private static double slope(double s, double p0, double m0, double p1, double m1) {
        double s2 = s * s;
        return (6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 + (6 * s - 6 * s2) * p1 + (3 * s2 - 2 * s) * m1;
    }
}
