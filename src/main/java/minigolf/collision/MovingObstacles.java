package minigolf.collision;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.HeightProbe;
import minigolf.course.Motion;
import minigolf.course.Obstacle;

/**
 * The course's moving (kinematic) obstacles as collision geometry (docs/physics.md, "Moving
 * obstacles"). Each keeps its body, still, as a {@link CollisionScene} of its own (placed as the
 * file gives it) and its {@link Motion}. A sweep of the ball's centre over a time interval is done
 * in each obstacle's frame: the ball's positions are carried back by the inverse of the obstacle's
 * pose at their times, so the body is still and its exact swept-sphere tests apply; the ball's path
 * in that frame, curved where the obstacle turns, is swept as chords that turn by at most
 * {@link #MAX_TURN} each, and a touching chord is swept again as shorter ones, so the contact lies on
 * the path to well under a micrometre. A sliding obstacle's path is cut at its corners, where its
 * velocity jumps: between them the ball's path in its frame is straight. Immutable; the per-thread
 * buffers are a {@link Sweeper}'s.
 */
public final class MovingObstacles {
    /** The most a chord of the ball's path may turn with the obstacle (rad): its sagitta is R·θ²/8. */
    static final double MAX_TURN = 0.02;
    /** A touching chord is swept again as 4 chords, this many times over. */
    static final int REFINEMENTS = 2;

    private final Entry[] entries;
    private final double radius;

    /**
     * One moving obstacle; {@code axis} for one that turns (rotates or swings): the pivot, the unit
     * axis and the farthest its body (grown by the ball's radius) comes from the axis,
     * {cx, cy, cz, kx, ky, kz, radius}; null for a slide.
     */
    private record Entry(int index, Motion motion, CollisionScene body, double[] reach, double[] axis, double restitution) {
        /**
         * Whether the ball's centre on the segment p0-p1 stays farther from the turning axis than
         * the body ever reaches: then no pose can touch it (a blade turning above the ground never
         * comes down to a ball beside the door it guards, though its box of reach is over it).
         * The distance from a line changes no faster than along the segment, so its least is
         * at least the nearer end's less half the segment's length.
         */
        boolean outOfReach(double x0, double y0, double z0, double x1, double y1, double z1) {
            if (axis == null) return false;
            double dx = x1 - x0, dy = y1 - y0, dz = z1 - z0;
            double half = 0.5 * Math.sqrt(dx * dx + dy * dy + dz * dz);
            return Math.min(fromAxis(x0, y0, z0), fromAxis(x1, y1, z1)) - half > axis[6];
        }

        /** The distance of (x, y, z) from the turning axis. */
        private double fromAxis(double x, double y, double z) {
            double[] a = axis;
            double px = x - a[0], py = y - a[1], pz = z - a[2];
            double along = px * a[3] + py * a[4] + pz * a[5];
            double rx = px - along * a[3], ry = py - along * a[4], rz = pz - along * a[5];
            return Math.sqrt(rx * rx + ry * ry + rz * rz);
        }
    }

    /** The box round every entry's reach in the plane (minX, minY, maxX, maxY): most questions end there. */
    private final double[] reachAll = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};

    private MovingObstacles(Entry[] entries, double radius) {
        this.entries = entries;
        this.radius = radius;
        for (Entry e : entries) {
            reachAll[0] = Math.min(reachAll[0], e.reach[0]);
            reachAll[1] = Math.min(reachAll[1], e.reach[1]);
            reachAll[2] = Math.max(reachAll[2], e.reach[3]);
            reachAll[3] = Math.max(reachAll[3], e.reach[4]);
        }
    }

    /** The moving obstacles among the course's (their indices kept), or null when none moves. */
    public static MovingObstacles build(List<Obstacle> obstacles, HeightProbe ground, Bounds bounds, double ballRadius) {
        List<Entry> list = new ArrayList<>();
        for (int k = 0; k < obstacles.size(); k++) {
            if (!(obstacles.get(k) instanceof Obstacle.Moving m)) continue;
            CollisionScene body = CollisionScene.build(List.of(m.body()), ground, bounds, ballRadius);
            // The scene numbers its one obstacle 0; contacts are reported with the course's index.
            list.add(new Entry(k, m.motion(), body, reach(body.extent(), m.motion(), ballRadius),
                    axis(body.extent(), m.motion(), ballRadius), m.restitution()));
        }
        return list.isEmpty() ? null : new MovingObstacles(list.toArray(new Entry[0]), ballRadius);
    }

    /**
     * For a body that turns about an axis: {cx, cy, cz, kx, ky, kz, radius}, the pivot, the unit
     * axis and the farthest the body comes from the axis, grown by the ball's radius and a hair
     * for rounding; null for a slide.
     */
    private static double[] axis(double[] e, Motion motion, double r) {
        double[] t = turning(e, motion);
        if (t == null) return null;
        return new double[] {t[0], t[1], t[2], t[3], t[4], t[5], t[6] + r + 1e-9 * (1 + t[6])};
    }

    /**
     * Turning about an axis k through the pivot c, a point keeps its position s along the axis and
     * its distance rho from it; s is linear and rho convex over the body's box, so both take their
     * extremes at its corners: {cx, cy, cz, kx, ky, kz, the largest rho, the least s, the largest s}
     * (k a unit vector); null for a slide.
     */
    private static double[] turning(double[] e, Motion motion) {
        if (motion instanceof Motion.Slide) return null;
        var pivot = motion instanceof Motion.Rotate rt ? rt.pivot() : ((Motion.Swing) motion).pivot();
        var axis = motion instanceof Motion.Rotate rt ? rt.axis() : ((Motion.Swing) motion).axis();
        double norm = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        double kx = axis.x() / norm, ky = axis.y() / norm, kz = axis.z() / norm;
        double along0 = Double.POSITIVE_INFINITY, along1 = Double.NEGATIVE_INFINITY, far = 0;
        for (int corner = 0; corner < 8; corner++) {
            double dx = ((corner & 1) == 0 ? e[0] : e[3]) - pivot.x();
            double dy = ((corner & 2) == 0 ? e[1] : e[4]) - pivot.y();
            double dz = ((corner & 4) == 0 ? e[2] : e[5]) - pivot.z();
            double along = dx * kx + dy * ky + dz * kz;
            double px = dx - along * kx, py = dy - along * ky, pz = dz - along * kz;
            along0 = Math.min(along0, along);
            along1 = Math.max(along1, along);
            far = Math.max(far, Math.sqrt(px * px + py * py + pz * pz));
        }
        return new double[] {pivot.x(), pivot.y(), pivot.z(), kx, ky, kz, far, along0, along1};
    }

    /** Everywhere the body can be over a period, grown by the ball's radius: {minX, minY, minZ, maxX, maxY, maxZ}. */
    private static double[] reach(double[] e, Motion motion, double r) {
        double[] box = new double[6];
        if (motion instanceof Motion.Slide s) {
            double lx = 0, ly = 0, lz = 0, hx = 0, hy = 0, hz = 0;
            for (var p : s.path()) {
                lx = Math.min(lx, p.x());
                ly = Math.min(ly, p.y());
                lz = Math.min(lz, p.z());
                hx = Math.max(hx, p.x());
                hy = Math.max(hy, p.y());
                hz = Math.max(hz, p.z());
            }
            double[] low = {lx, ly, lz}, high = {hx, hy, hz};
            for (int k = 0; k < 3; k++) {
                box[k] = e[k] + low[k] - r;
                box[k + 3] = e[k + 3] + high[k] + r;
            }
            return box;
        }
        // Coordinate j stays within c_j + s k_j +- rho sqrt(1 - k_j^2) (a blade turning about x
        // keeps its own x extent).
        double[] t = turning(e, motion);
        double far = t[6], along0 = t[7], along1 = t[8];
        for (int j = 0; j < 3; j++) {
            double kj = t[3 + j];
            double spread = far * Math.sqrt(Math.max(0, 1 - kj * kj));
            // Rounding: the box may only grow.
            double slack = 1e-9 * (1 + far + Math.abs(along0) + Math.abs(along1));
            box[j] = t[j] + Math.min(along0 * kj, along1 * kj) - spread - r - slack;
            box[j + 3] = t[j] + Math.max(along0 * kj, along1 * kj) + spread + r + slack;
        }
        return box;
    }

    public int size() {
        return entries.length;
    }

    /** Whether a moving obstacle can ever come within a ball radius of the rectangle (centre positions). */
    public boolean anyNear(double minX, double minY, double maxX, double maxY) {
        if (reachAll[0] > maxX || reachAll[2] < minX || reachAll[1] > maxY || reachAll[3] < minY) return false;
        for (Entry e : entries) {
            if (e.reach[0] <= maxX && e.reach[3] >= minX && e.reach[1] <= maxY && e.reach[4] >= minY) return true;
        }
        return false;
    }

    /**
     * Whether some moving obstacle may touch the ball's centre somewhere on the segment p0-p1 at
     * some moment: the segment meets its box of reach and, for one that turns, comes within its
     * reach of the axis. Sweeps and still contacts look no further where this is false.
     */
    boolean mayReach(double x0, double y0, double z0, double x1, double y1, double z1) {
        for (Entry e : entries) {
            double[] b = e.reach;
            if (b[0] > Math.max(x0, x1) || b[3] < Math.min(x0, x1) || b[1] > Math.max(y0, y1) || b[4] < Math.min(y0, y1)
                    || b[2] > Math.max(z0, z1) || b[5] < Math.min(z0, z1)) continue;
            if (!e.outOfReach(x0, y0, z0, x1, y1, z1)) return true;
        }
        return false;
    }

    /** A new set of buffers for sweeps on one thread. */
    public Sweeper sweeper() {
        return new Sweeper();
    }

    /** Sweeps against the moving obstacles with buffers of its own (one per stroke, not shared between threads). */
    public final class Sweeper {
        private final double[] pose = new double[12], scratch = new double[3], velocity = new double[9];
        private final Hit local = new Hit();
        // The sweep in progress: the world chord and its times.
        private double x0, y0, z0, x1, y1, z1, t0, t1;
        private Entry entry;
        private double bestTime;

        private Sweeper() {
        }

        /**
         * Sweeps the ball's centre along the straight chord from p0 at course clock t0 to p1 at t1
         * (the ball moving along it at a constant rate) against every moving obstacle. On a contact
         * at a fraction of the chord below {@code limit} fills {@code hit} (normal, restitution, the
         * obstacle's index and the velocity of its surface there) and returns the fraction; else
         * +infinity. The contact is moved back by {@code skin} (m) along the chord in the obstacle's frame.
         */
        public double sweep(double x0, double y0, double z0, double t0, double x1, double y1, double z1, double t1,
                            double limit, double skin, Hit hit) {
            this.x0 = x0;
            this.y0 = y0;
            this.z0 = z0;
            this.x1 = x1;
            this.y1 = y1;
            this.z1 = z1;
            this.t0 = t0;
            this.t1 = t1;
            lastEntry = null;
            double best = limit;
            double minX = Math.min(x0, x1), maxX = Math.max(x0, x1), minY = Math.min(y0, y1), maxY = Math.max(y0, y1);
            double minZ = Math.min(z0, z1), maxZ = Math.max(z0, z1);
            for (Entry e : entries) {
                double[] b = e.reach;
                if (b[0] > maxX || b[3] < minX || b[1] > maxY || b[4] < minY || b[2] > maxZ || b[5] < minZ) continue;
                if (e.outOfReach(x0, y0, z0, x1, y1, z1)) continue;
                entry = e;
                double f = sweepEntry(best, skin);
                if (f < best) {
                    best = f;
                    contact(e, hit, f);
                }
            }
            return best < limit ? best : Double.POSITIVE_INFINITY;
        }

        /**
         * The first contact of a ball whose centre stays at (x, y, z) from course clock t on, within
         * one period of each obstacle (they repeat, so a ball not touched within it is never touched):
         * the clock at the contact, with {@code hit} filled, or +infinity.
         */
        public double stillContact(double x, double y, double z, double t, Hit hit) {
            double best = Double.POSITIVE_INFINITY;
            double r = radius;
            for (Entry e : entries) {
                double[] b = e.reach;
                if (b[0] > x || b[3] < x || b[1] > y || b[4] < y || b[2] > z || b[5] < z) continue;
                if (e.outOfReach(x, y, z, x, y, z)) continue;
                this.x0 = x;
                this.y0 = y;
                this.z0 = z;
                this.x1 = x;
                this.y1 = y;
                this.z1 = z;
                this.t0 = t;
                this.t1 = t + Math.min(e.motion.period(), best - t);
                lastEntry = null;
                if (!(t1 > t0)) continue;
                entry = e;
                double f = sweepEntry(1, 0);
                if (f <= 1) {
                    best = t0 + f * (t1 - t0);
                    contact(e, hit, f);
                }
            }
            return best;
        }

        /** The contact with entry e at fraction f of the sweep: the world normal and the surface's velocity. */
        private void contact(Entry e, Hit hit, double f) {
            double time = bestTime;
            e.motion.poseAt(time, pose);
            double nx = pose[0] * local.nx + pose[1] * local.ny + pose[2] * local.nz;
            double ny = pose[3] * local.nx + pose[4] * local.ny + pose[5] * local.nz;
            double nz = pose[6] * local.nx + pose[7] * local.ny + pose[8] * local.nz;
            hit.fraction = f;
            hit.nx = nx;
            hit.ny = ny;
            hit.nz = nz;
            hit.restitution = e.restitution;
            hit.obstacle = e.index;
            hit.moving = true;
            hit.brick = -1;
            // The surface's velocity at the contact point (the ball's centre less a radius along n).
            double px = x0 + f * (x1 - x0) - radius * nx, py = y0 + f * (y1 - y0) - radius * ny, pz = z0 + f * (z1 - z0) - radius * nz;
            e.motion.velocityAt(time, velocity);
            double rx = px - velocity[3], ry = py - velocity[4], rz = pz - velocity[5];
            hit.ux = velocity[1] * rz - velocity[2] * ry + velocity[6];
            hit.uy = velocity[2] * rx - velocity[0] * rz + velocity[7];
            hit.uz = velocity[0] * ry - velocity[1] * rx + velocity[8];
        }

        /** The first contact fraction (below limit) of the current sweep with the current entry; sets bestTime and local. */
        private double sweepEntry(double limit, double skin) {
            double span = t1 - t0;
            int pieces = pieces(entry.motion, t0, t1);
            // A sliding obstacle turns a corner of its path at known times: the pieces end there.
            double[] cuts = entry.motion instanceof Motion.Slide s ? corners(s, t0, t1) : null;
            double sa = 0;
            int cut = 0;
            for (int k = 1; k <= pieces; k++) {
                double sb = (double) k / pieces;
                while (cuts != null && cut < cuts.length && cuts[cut] < sb) {
                    double f = range(sa, cuts[cut], limit, skin, REFINEMENTS);
                    if (f < limit) return f;
                    sa = cuts[cut++];
                }
                if (sa >= limit) return Double.POSITIVE_INFINITY;
                double f = range(sa, sb, limit, skin, REFINEMENTS);
                if (f < limit) return f;
                sa = sb;
            }
            return Double.POSITIVE_INFINITY;
        }

        /**
         * Sweeps the part [sa, sb] of the current sweep (fractions of it) as one chord in the
         * obstacle's frame; where it touches and refinements are left, as 4 chords. Returns the
         * fraction of the contact, or +infinity.
         */
        private double range(double sa, double sb, double limit, double skin, int refinements) {
            double ax, ay, az, bx, by, bz;
            localPoint(sa);
            ax = scratch[0];
            ay = scratch[1];
            az = scratch[2];
            localPoint(sb);
            bx = scratch[0];
            by = scratch[1];
            bz = scratch[2];
            if (!entry.body.sweep(ax, ay, az, bx, by, bz, local, scratch)) return Double.POSITIVE_INFINITY;
            double f = sa + local.fraction * (sb - sa);
            if (f >= limit) return Double.POSITIVE_INFINITY;
            if (refinements > 0) {
                for (int j = 0; j < 4; j++) {
                    double ca = sa + 0.25 * j * (sb - sa), cb = j == 3 ? sb : sa + 0.25 * (j + 1) * (sb - sa);
                    double g = range(ca, cb, limit, skin, refinements - 1);
                    if (g < limit) return g;
                }
                // The finer chords missed what the coarse one grazed: no contact on the path.
                return Double.POSITIVE_INFINITY;
            }
            double chord = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay) + (bz - az) * (bz - az));
            double back = chord > 0 ? local.fraction - skin / chord : local.fraction;
            f = sa + Math.max(0, back) * (sb - sa);
            bestTime = t0 + f * (t1 - t0);
            return f;
        }

        /** The ball's centre at fraction s of the current sweep, in the obstacle's frame, into scratch. */
        private void localPoint(double s) {
            // A chord starts where the one before ended: that point is kept, not posed again.
            if (entry == lastEntry && s == lastS) {
                scratch[0] = lastX;
                scratch[1] = lastY;
                scratch[2] = lastZ;
                return;
            }
            double time = t0 + s * (t1 - t0);
            double px = x0 + s * (x1 - x0), py = y0 + s * (y1 - y0), pz = z0 + s * (z1 - z0);
            entry.motion.poseAt(time, pose);
            // p = R q + T, so q = R^T (p - T).
            double dx = px - pose[9], dy = py - pose[10], dz = pz - pose[11];
            scratch[0] = pose[0] * dx + pose[3] * dy + pose[6] * dz;
            scratch[1] = pose[1] * dx + pose[4] * dy + pose[7] * dz;
            scratch[2] = pose[2] * dx + pose[5] * dy + pose[8] * dz;
            lastEntry = entry;
            lastS = s;
            lastX = scratch[0];
            lastY = scratch[1];
            lastZ = scratch[2];
        }

        /** The last point localPoint gave (of lastEntry, at lastS of the current sweep); forgotten with each new sweep. */
        private Entry lastEntry;
        private double lastS, lastX, lastY, lastZ;
    }

    /** Chords for [t0, t1]: each turns by at most {@link #MAX_TURN} (one for a slide, which is cut at its corners). */
    private static int pieces(Motion motion, double t0, double t1) {
        double turn;
        if (motion instanceof Motion.Rotate r) {
            turn = 2 * Math.PI * (t1 - t0) / r.period();
        } else if (motion instanceof Motion.Swing s) {
            turn = Math.toRadians(s.amplitudeDeg()) * 2 * Math.PI / s.period() * (t1 - t0);
        } else {
            return 1;
        }
        return Math.max(1, (int) Math.ceil(turn / MAX_TURN));
    }

    /** The fractions of [t0, t1] at which a sliding obstacle passes a corner of its path, in order. */
    private static double[] corners(Motion.Slide s, double t0, double t1) {
        int n = s.path().size();
        int legs = s.closed() ? n : 2 * (n - 1);
        double travel = s.travel();
        double[] at = new double[legs];
        double along = 0;
        for (int leg = 0; leg < legs; leg++) {
            int a = s.closed() ? leg % n : (leg < n ? leg : 2 * (n - 1) - leg);
            int b = s.closed() ? (leg + 1) % n : (leg + 1 < n ? leg + 1 : 2 * (n - 1) - leg - 1);
            var p = s.path().get(a);
            var q = s.path().get(b);
            along += Math.sqrt((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y())
                    + (q.z() - p.z()) * (q.z() - p.z()));
            at[leg] = along / travel;
        }
        List<Double> cuts = new ArrayList<>();
        double period = s.period();
        double first = Math.floor((t0 + s.phase()) / period);
        for (double cycle = first; (cycle * period) - s.phase() < t1; cycle++) {
            for (int leg = -1; leg < legs; leg++) {
                double time = (cycle + (leg < 0 ? 0 : at[leg])) * period - s.phase();
                if (time > t0 && time < t1) cuts.add((time - t0) / (t1 - t0));
            }
        }
        double[] out = new double[cuts.size()];
        for (int i = 0; i < out.length; i++) out[i] = cuts.get(i);
        java.util.Arrays.sort(out);
        return out;
    }
}
