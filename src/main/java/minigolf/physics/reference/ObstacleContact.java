package minigolf.physics.reference;

import minigolf.collision.CollisionScene;
import minigolf.collision.Hit;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * Obstacle contacts of a rolling ball on the dense output, and the rolling collision response of
 * docs/physics.md. The time of impact on the curved path is found by bisection: the scene's sweep
 * (exact geometry on a straight chord) is asked whether the chord from the last clear time to a
 * trial time touches anything; as the bracket shrinks, the chord converges to the path.
 */
final class ObstacleContact {
    /** A bounce off the ground's plane faster than a 1 mm hop, √(2g·1 mm), flies. */
    private final double hopSpeed;
    private final CollisionScene scene;
    private final Terrain terrain;
    private final DormandPrince stepper;
    private final double radius;
    /** Flying: the state is (x, y, z, ...) with z the ball's bottom; rolling: (x, y, ...) on the ground. */
    private final boolean flying;
    private final Hit hit = new Hit();
    private final double[] scratch = new double[3], a = new double[6], b = new double[6], sample = new double[3];

    /** The last contact: the time just before touching, the contact normal and the restitution. */
    double time, nx, ny, nz, restitution;
    /** The velocity a rolling ball flies off with when {@link #respond} returns false. */
    final double[] flight = new double[3];

    ObstacleContact(World world, DormandPrince stepper, boolean flying) {
        this.flying = flying;
        this.scene = world.obstacles();
        this.terrain = world.terrain();
        this.stepper = stepper;
        this.radius = world.physics().ballRadius();
        this.hopSpeed = Math.sqrt(2 * world.physics().gravity() * 1e-3);
    }

    boolean hasObstacles() {
        return scene != null && !scene.isEmpty();
    }

    /** Whether the path in [from, to] of the last accepted step touches an obstacle; if so sets {@link #time}. */
    boolean find(double from, double to) {
        if (!hasObstacles()) return false;
        int pieces = 4;
        double sa = from;
        for (int s = 1; s <= pieces; s++) {
            double sb = s == pieces ? to : from + (to - from) * s / pieces;
            if (chordHits(sa, sb)) {
                return refine(sa, sb);
            }
            sa = sb;
        }
        return false;
    }

    /**
     * Bisects the first touching time in [lo, hi], keeping "the chord [lo, hi] touches"; false if
     * neither half touches (the chord cut a corner the curved path misses).
     */
    private boolean refine(double lo, double hi) {
        while (hi - lo > EventLocator.TIME_TOLERANCE) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            if (chordHits(lo, mid)) {
                hi = mid;
            } else {
                lo = mid;
                if (!chordHits(lo, hi)) return false;
            }
        }
        time = lo;
        return true;
    }

    private boolean chordHits(double t0, double t1) {
        stepper.interpolate(t0, a);
        stepper.interpolate(t1, b);
        double minX = Math.min(a[0], b[0]) - radius, maxX = Math.max(a[0], b[0]) + radius;
        double minY = Math.min(a[1], b[1]) - radius, maxY = Math.max(a[1], b[1]) + radius;
        if (!scene.anyNear(minX, minY, maxX, maxY)) return false;
        // The collision sphere's centre is the contact point lifted by the radius (docs/physics.md).
        double za = (flying ? a[2] : terrain.height(a[0], a[1])) + radius;
        double zb = (flying ? b[2] : terrain.height(b[0], b[1])) + radius;
        if (!scene.sweep(a[0], a[1], za, b[0], b[1], zb, hit, scratch)) return false;
        nx = hit.nx;
        ny = hit.ny;
        nz = hit.nz;
        restitution = hit.restitution;
        return true;
    }

    /** The flying response: v' = v − (1 + e)(v·n)n on the velocity (v[at], v[at+1], v[at+2]); returns the normal speed after. */
    double reflect(double[] v, int at) {
        double vn = v[at] * nx + v[at + 1] * ny + v[at + 2] * nz;
        if (vn < 0) {
            double k = (1 + restitution) * vn;
            v[at] -= k * nx;
            v[at + 1] -= k * ny;
            v[at + 2] -= k * nz;
            return -restitution * vn;
        }
        return vn;
    }

    /**
     * The rolling response at state y: the velocity along the ground (vx, vy, ∇h·v) is reflected
     * off the contact normal with the obstacle's restitution; if it then leaves the ground faster
     * than a 1 mm hop the ball flies (returns false, the reflected velocity in {@link #flight}),
     * otherwise the part off the ground's plane is removed and y's velocity set to what is left.
     */
    boolean respond(double[] y) {
        terrain.sample(y[0], y[1], sample);
        double hx = sample[1], hy = sample[2];
        double vx = y[2], vy = y[3], vz = hx * vx + hy * vy;
        double vn = vx * nx + vy * ny + vz * nz;
        if (vn < 0) {
            double k = (1 + restitution) * vn;
            vx -= k * nx;
            vy -= k * ny;
            vz -= k * nz;
        }
        double norm = Math.sqrt(1 + hx * hx + hy * hy);
        double gx = -hx / norm, gy = -hy / norm, gz = 1 / norm;
        double up = vx * gx + vy * gy + vz * gz;
        if (up > hopSpeed) {
            flight[0] = vx;
            flight[1] = vy;
            flight[2] = vz;
            return false;
        }
        y[2] = vx - up * gx;
        y[3] = vy - up * gy;
        return true;
    }
}
