package minigolf.physics;

import minigolf.collision.Hit;
import minigolf.terrain.Terrain;

/**
 * Sweeps the ball's sphere along a step's path against the obstacles (docs/physics.md,
 * "Continuous collision"): the contact found is in {@link #hit}, {@link #contactAt} and the
 * contact point.
 */
final class PathSweep {
    /** Chords a step's path is swept as, against the obstacles, where it turns... */
    static final int PATH_PIECES = 4;
    /** ... by more than this from its chord (m); a straighter path is swept as its chord. */
    static final double STRAIGHT = 1e-6;
    /**
     * Where a chord meets an obstacle, the path between its ends is swept again as 4 chords, this
     * many times over: the contact lies on the curve to within its 1/64th chords' sagitta.
     */
    static final int REFINEMENTS = 2;
    /** A ball stops this far short of its contact point along its path, so it never ends a step touching. */
    static final double SKIN = 1e-7;

    private final Solids solids;
    private final Terrain terrain;
    private final double ballRadius;
    /** The stroke's ball (its time is the step's start) and the course clock when the stroke began. */
    private final BallState ball;
    private double startClock;
    /** The last contact: normal, restitution, fraction of the chord it was found on. */
    final Hit hit = new Hit();
    /** The last contact: the fraction of the step, and the sphere's centre there. */
    double contactAt, contactX, contactY, contactZ;
    // The path being swept: the Hermite curve's ends and tangents, and whether it rolls; a point on it.
    private double x0, y0, z0, mx0, my0, mz0, x1, y1, z1, mx1, my1, mz1;
    private boolean rolling;
    private double px, py, pz;
    // The course clock at the step's start, and its length: the moving obstacles' times.
    private double clock0, tau;

    PathSweep(Solids solids, Terrain terrain, double ballRadius, BallState ball) {
        this.solids = solids;
        this.ball = ball;
        this.terrain = terrain;
        this.ballRadius = ballRadius;
    }

    /** A new stroke played at course clock {@code clock}. */
    void start(double clock) {
        startClock = clock;
    }

    /**
     * Sweeps the ball's sphere along its path through a step of length tau, from (x0, y0, z0) at
     * velocity v0 to (x1, y1, z1) at v1 (z the sphere's centre), against the obstacles. The path is
     * the cubic Hermite curve through both ends with their velocities, swept as
     * {@link #PATH_PIECES} chords: a single chord cuts the curve's corner by up to a tau^2 / 8
     * (0.3 mm at 1/60 s), enough to turn a glancing hit on a trunk into a miss; the chord that
     * meets an obstacle is refined ({@link #REFINEMENTS}), so the contact's time and place are the
     * curve's, not the chord's (a contact a few µm off moved balls by millimetres after several
     * contacts on `lake-obstacles`). A rolling ball's
     * centre follows the ground (z from the terrain; z0 the centre's height at the start, z1
     * ignored). On a contact returns true
     * with {@link #contactAt} (the fraction of tau) and the contact point set, backed off by
     * {@link #SKIN}.
     */
    boolean sweep(double x0, double y0, double z0, double vx0, double vy0, double vz0,
                  double x1, double y1, double z1, double vx1, double vy1, double vz1,
                  double tau, boolean rolling) {
        double ax = x0, ay = y0, az = z0;
        double loX = Math.min(x0, x1), loY = Math.min(y0, y1), hiX = Math.max(x0, x1), hiY = Math.max(y0, y1);
        // The curve strays from the chord by at most |v0 - v1| tau / 8 (a cubic's bound is smaller).
        double bulge = 0.125 * tau * (Math.abs(vx0 - vx1) + Math.abs(vy0 - vy1));
        if (!solids.anyNear(loX - bulge, loY - bulge, hiX + bulge, hiY + bulge)) return false;
        // Every point of the Hermite curve lies within (4/27)(|v0 tau - c| + |v1 tau - c|) of its
        // chord c, so every chord swept below stays that close to c: with no shape near it, no
        // sweep can meet one, and the terrain samples and sweeps of the chords are saved.
        double ex0 = vx0 * tau - (x1 - x0), ey0 = vy0 * tau - (y1 - y0);
        double ex1 = vx1 * tau - (x1 - x0), ey1 = vy1 * tau - (y1 - y0);
        double reach = 4.0 / 27 * (Math.sqrt(ex0 * ex0 + ey0 * ey0) + Math.sqrt(ex1 * ex1 + ey1 * ey1)) * (1 + 1e-9) + 1e-12;
        if (!solids.anyShapeNearPath(x0, y0, x1, y1, reach)) return false;
        // A path that does not turn (the velocity changes only along the chord, as on flat ground)
        // is its chord: one sweep. Sideways, the cubic strays by about |dv x chord| tau / 8.
        double cx = x1 - x0, cy = y1 - y0, chord = Math.sqrt(cx * cx + cy * cy);
        double sideways = chord > 0 ? Math.abs((vx0 - vx1) * cy - (vy0 - vy1) * cx) / chord : bulge;
        double vertical = rolling ? 0 : Math.abs(vz0 - vz1) + Math.abs(z1 - z0 - 0.5 * (vz0 + vz1) * tau) / tau;
        int pieces = 0.125 * tau * (sideways + vertical) < STRAIGHT ? 1 : PATH_PIECES;
        // A straight rolling path on ground that is plane along it, with no moving obstacle
        // within reach: its chord is its path, and the refinement's chords lie on the chord.
        straight = pieces == 1 && rolling && !solids.anyMovingNear(loX - bulge, loY - bulge, hiX + bulge, hiY + bulge);
        this.x0 = x0;
        this.y0 = y0;
        this.z0 = z0;
        this.x1 = x1;
        this.y1 = y1;
        this.z1 = z1;
        mx0 = vx0 * tau;
        my0 = vy0 * tau;
        mz0 = vz0 * tau;
        mx1 = vx1 * tau;
        my1 = vy1 * tau;
        mz1 = vz1 * tau;
        this.rolling = rolling;
        this.clock0 = startClock + ball.t;
        this.tau = tau;
        double s0 = 0;
        for (int k = 1; k <= pieces; k++) {
            double s1 = (double) k / pieces;
            pointAt(s1);
            double bx = px, by = py, bz = pz;
            if (sweepRange(s0, s1, ax, ay, az, bx, by, bz, REFINEMENTS)) return true;
            ax = bx;
            ay = by;
            az = bz;
            s0 = s1;
        }
        return false;
    }

    /**
     * The end of the j-th (1 to 4) of four equal pieces of [sa, sb] into (px, py, pz): the path
     * there, or b itself for the last; returns its s.
     */
    private double quarter(int j, double sa, double sb, double bx, double by, double bz) {
        if (j == 4) {
            px = bx;
            py = by;
            pz = bz;
            return sb;
        }
        double s = sa + 0.25 * j * (sb - sa);
        pointAt(s);
        return s;
    }

    /** The sphere's centre on the path at s (the ends exactly). */
    private void pointAt(double s) {
        if (s >= 1) {
            px = x1;
            py = y1;
            pz = rolling ? terrain.height(x1, y1) + ballRadius : z1;
            return;
        }
        px = hermite(s, x0, mx0, x1, mx1);
        py = hermite(s, y0, my0, y1, my1);
        pz = rolling ? terrain.height(px, py) + ballRadius : hermite(s, z0, mz0, z1, mz1);
    }

    /**
     * Sweeps the chord from a (the path at sa) to b (at sb); where it meets an obstacle and
     * refinements are left, the path between is swept again as 4 shorter chords, so the contact
     * found lies on the curve (to the last chords' sagitta) and not on a chord that cuts its corner.
     */
    private boolean sweepRange(double sa, double sb, double ax, double ay, double az,
                               double bx, double by, double bz, int refinements) {
        if (!solids.sweep(ax, ay, az, clock0 + sa * tau, bx, by, bz, clock0 + sb * tau, SKIN, hit)) return false;
        if (refinements == REFINEMENTS && straight && !hit.moving && alongLine(ax, ay, az, bx, by, bz)) return true;
        if (refinements == 0) {
            // A moving obstacle's contact is already backed off, in its own frame.
            if (!hit.moving) backOff(Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay) + (bz - az) * (bz - az)));
            double f = hit.fraction;
            contactX = ax + f * (bx - ax);
            contactY = ay + f * (by - ay);
            contactZ = az + f * (bz - az);
            contactAt = sa + f * (sb - sa);
            return true;
        }
        double ca = sa, cx = ax, cy = ay, cz = az;
        for (int j = 1; j <= 4; j++) {
            double cb = quarter(j, sa, sb, bx, by, bz);
            double dx = px, dy = py, dz = pz;
            if (sweepRange(ca, cb, cx, cy, cz, dx, dy, dz, refinements - 1)) return true;
            ca = cb;
            cx = dx;
            cy = dy;
            cz = dz;
        }
        return false;
    }

    /** Whether the path being swept is one straight chord with no moving obstacle near (see sweep). */
    private boolean straight;

    /**
     * Where the path's chord from a to b met a still obstacle (hit.fraction of it), the contact
     * as the refinement's sweeps would find it, without them: on a straight path the chords of
     * the refinement (the path at sixteenths of the step) lie on the chord, so the first contact
     * on them is the chord's, in the sixteenth whose ends lie either side of it; the contact's
     * time is its fraction of that sixteenth, backed off by SKIN along it, as there. False
     * (nothing set) where the path's points leave the chord by more than {@link #ON_LINE}, or
     * do not advance along it: then the refinement sweeps.
     */
    private boolean alongLine(double ax, double ay, double az, double bx, double by, double bz) {
        double dx = bx - ax, dy = by - ay, dz = bz - az, squared = dx * dx + dy * dy + dz * dz;
        if (!(squared > 0)) return false;
        double f = hit.fraction;
        double sa = 0, ta = 0, pax = ax, pay = ay, paz = az;
        double sb = 1, pbx = bx, pby = by, pbz = bz;
        for (int level = 0; level < REFINEMENTS; level++) {
            // The four pieces of [sa, sb]: the first whose end lies at or past the contact holds it.
            double s0 = sa, t0 = ta, p0x = pax, p0y = pay, p0z = paz;
            double stop = sb;
            for (int j = 1; j <= 4; j++) {
                double s1 = quarter(j, sa, stop, pbx, pby, pbz);
                double p1x = px, p1y = py, p1z = pz;
                double rx = p1x - ax, ry = p1y - ay, rz = p1z - az;
                double t1 = (rx * dx + ry * dy + rz * dz) / squared;
                // Off the chord (by its distance), or not advancing along it: refine as before.
                double ox = rx - t1 * dx, oy = ry - t1 * dy, oz = rz - t1 * dz;
                if (!(ox * ox + oy * oy + oz * oz <= ON_LINE * ON_LINE) || !(t1 > t0)) return false;
                if (t1 >= f || j == 4) {
                    sa = s0;
                    ta = t0;
                    pax = p0x;
                    pay = p0y;
                    paz = p0z;
                    sb = s1;
                    pbx = p1x;
                    pby = p1y;
                    pbz = p1z;
                    break;
                }
                s0 = s1;
                t0 = t1;
                p0x = p1x;
                p0y = p1y;
                p0z = p1z;
            }
        }
        double tb = ((pbx - ax) * dx + (pby - ay) * dy + (pbz - az) * dz) / squared;
        double qx = pbx - pax, qy = pby - pay, qz = pbz - paz, length = Math.sqrt(qx * qx + qy * qy + qz * qz);
        double g = Math.min(1, Math.max(0, (f - ta) / (tb - ta)));
        if (length > 0) g = Math.max(0, g - SKIN / length);
        hit.fraction = g;
        contactX = pax + g * qx;
        contactY = pay + g * qy;
        contactZ = paz + g * qz;
        contactAt = sa + g * (sb - sa);
        return true;
    }

    /**
     * How far (m) the path's points may lie from its chord for {@link #alongLine}. Far below the
     * 1e-6 m that makes a path straight enough to be swept as one chord: a contact a micrometre
     * off turns a glancing bounce by 1e-6 / r rad, and at 2e-6 m the worst shot of 18-finale
     * moved from 15 to 260 µm off the reference (08-funnel 42 -> 500 µm).
     */
    static final double ON_LINE = 1e-9;

    /** The cubic Hermite curve at s in [0, 1] from p0 with tangent m0 to p1 with tangent m1. */
    static double hermite(double s, double p0, double m0, double p1, double m1) {
        double s2 = s * s, s3 = s2 * s;
        return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (3 * s2 - 2 * s3) * p1 + (s3 - s2) * m1;
    }

    /** Moves the contact fraction back by {@link #SKIN} along a sweep of the given length. */
    private void backOff(double length) {
        if (length > 0) hit.fraction = Math.max(0, hit.fraction - SKIN / length);
    }

}
