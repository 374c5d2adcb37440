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
    /** The velocity of the surface hit (0 for a still obstacle or a gate), and whether it moves. */
    double ux, uy, uz;
    boolean moving;
    /** The course clock when the stroke began: the moving obstacles' time is it plus the stroke's. */
    double clockOffset;
    private final ReferenceGates gates;
    private final ReferenceMoving movers;
    private final double maxSpeed, g;
    /** The velocity a rolling ball flies off with when {@link #respond} returns false. */
    final double[] flight = new double[3];

    ObstacleContact(World world, DormandPrince stepper, boolean flying) {
        this.flying = flying;
        this.scene = world.obstacles();
        this.terrain = world.terrain();
        this.stepper = stepper;
        this.radius = world.physics().ballRadius();
        this.hopSpeed = Math.sqrt(2 * world.physics().gravity() * 1e-3);
        this.gates = new ReferenceGates(world);
        this.movers = new ReferenceMoving(world);
        this.maxSpeed = world.physics().maxSpeed();
        this.g = world.physics().gravity();
    }

    boolean hasObstacles() {
        return (scene != null && !scene.isEmpty()) || !gates.none() || !movers.none();
    }

    ReferenceMoving movers() {
        return movers;
    }

    /** Whether the path in [from, to] of the last accepted step touches an obstacle; if so sets {@link #time}. */
    boolean find(double from, double to) {
        if (!hasObstacles()) return false;
        // Chords short enough that a turning obstacle turns by at most 5 mrad and a sliding one moves
        // at most 0.5 mm along one: the bisection below then converges on the path.
        double span = to - from;
        int pieces = (int) Math.max(4, Math.ceil(Math.max(movers.fastestTurn() * span / 0.005, movers.fastestSlide() * span / 5e-4)));
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
        boolean sceneNear = scene != null && scene.anyNear(minX, minY, maxX, maxY);
        if (!sceneNear && gates.none() && movers.none()) return false;
        // The collision sphere's centre is the contact point lifted by the radius (docs/physics.md).
        double za = (flying ? a[2] : terrain.height(a[0], a[1])) + radius;
        double zb = (flying ? b[2] : terrain.height(b[0], b[1])) + radius;
        moving = false;
        if (sceneNear && scene.sweep(a[0], a[1], za, b[0], b[1], zb, hit, scratch)) {
            nx = hit.nx;
            ny = hit.ny;
            nz = hit.nz;
            restitution = hit.restitution;
            ux = uy = uz = 0;
            return true;
        }
        if (!gates.none() && gates.touches(a[0], a[1], za, b[0], b[1], zb)) {
            nx = gates.nx;
            ny = gates.ny;
            nz = gates.nz;
            restitution = gates.restitution;
            ux = uy = uz = 0;
            return true;
        }
        if (!movers.none() && movers.touches(a[0], a[1], za, clockOffset + t0, b[0], b[1], zb, clockOffset + t1)) {
            nx = movers.nx;
            ny = movers.ny;
            nz = movers.nz;
            restitution = movers.restitution;
            movers.surfaceVelocity(a[0] - radius * nx, a[1] - radius * ny, za - radius * nz, clockOffset + t0);
            ux = movers.ux;
            uy = movers.uy;
            uz = movers.uz;
            moving = true;
            return true;
        }
        return false;
    }

    /**
     * The bounce of docs/physics.md, relative to the surface: the velocity (vx, vy, vz) less the
     * surface's has its normal part reversed and multiplied by the restitution, a bumper's capped so
     * the ball leaves (relative to it) no faster than max(maxSpeed, its speed before). Into out.
     */
    private void bounce(double vx, double vy, double vz, double[] out) {
        double wx = vx - ux, wy = vy - uy, wz = vz - uz;
        double wn = wx * nx + wy * ny + wz * nz;
        out[0] = vx;
        out[1] = vy;
        out[2] = vz;
        if (wn >= 0) return;
        double leave = -restitution * wn;
        if (restitution > 1) {
            double speed = Math.sqrt(wx * wx + wy * wy + wz * wz);
            double limit = Math.max(maxSpeed, speed);
            double tangential2 = speed * speed - wn * wn;
            leave = Math.min(leave, Math.sqrt(Math.max(0, limit * limit - tangential2)));
        }
        out[0] += (leave - wn) * nx;
        out[1] += (leave - wn) * ny;
        out[2] += (leave - wn) * nz;
    }

    private final double[] bounced = new double[3];

    /**
     * When (stroke time) a moving obstacle first touches a ball resting at (x, y) on ground of height
     * h, from time t0 until t0 + horizon: chords of the still ball's path in the obstacles' frames,
     * the first touching one bisected. NaN if none touches; else the time just before touching, with
     * the contact's normal, restitution and surface velocity set.
     */
    double firstTouchStill(double x, double y, double h, double t0, double horizon) {
        double z = h + radius;
        int pieces = (int) Math.max(8, Math.ceil(Math.max(movers.fastestTurn() * horizon / 0.005, movers.fastestSlide() * horizon / 5e-4)));
        double lo = t0;
        for (int k = 1; k <= pieces; k++) {
            double hi = t0 + horizon * k / pieces;
            if (movers.touches(x, y, z, clockOffset + lo, x, y, z, clockOffset + hi)) {
                while (hi - lo > EventLocator.TIME_TOLERANCE) {
                    double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    if (movers.touches(x, y, z, clockOffset + lo, x, y, z, clockOffset + mid)) {
                        hi = mid;
                    } else {
                        lo = mid;
                        if (!movers.touches(x, y, z, clockOffset + lo, x, y, z, clockOffset + hi)) break;
                    }
                }
                nx = movers.nx;
                ny = movers.ny;
                nz = movers.nz;
                restitution = movers.restitution;
                movers.surfaceVelocity(x - radius * nx, y - radius * ny, z - radius * nz, clockOffset + lo);
                ux = movers.ux;
                uy = movers.uy;
                uz = movers.uz;
                moving = true;
                return lo;
            }
            lo = hi;
        }
        return Double.NaN;
    }

    /** The flying response: v' = v − (1 + e)(v·n)n on the velocity (v[at], v[at+1], v[at+2]); returns the normal speed after. */
    double reflect(double[] v, int at) {
        bounce(v[at], v[at + 1], v[at + 2], bounced);
        v[at] = bounced[0];
        v[at + 1] = bounced[1];
        v[at + 2] = bounced[2];
        return (v[at] - ux) * nx + (v[at + 1] - uy) * ny + (v[at + 2] - uz) * nz;
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
        bounce(y[2], y[3], hx * y[2] + hy * y[3], bounced);
        double vx = bounced[0], vy = bounced[1], vz = bounced[2];
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

    /**
     * After a moving obstacle's contact that left the ball rolling at state y (its rule for the
     * least separation, docs/physics.md): relative to the surface, along the normal, the ball leaves
     * at least at √(2 g (μk + |P|) 1 mm), the speed added along the normal's part in the ground's
     * plane; {@code pull} is |P| and {@code muK} the friction there.
     */
    void separate(double[] y, double muK, double pull) {
        terrain.sample(y[0], y[1], sample);
        double hx = sample[1], hy = sample[2];
        double least = Math.sqrt(2 * g * (muK + pull) * 1e-3);
        double vz = hx * y[2] + hy * y[3];
        double away = (y[2] - ux) * nx + (y[3] - uy) * ny + (vz - uz) * nz;
        if (away >= least) return;
        // The normal projected on the ground's plane: n - m (m . n), m the ground's unit normal.
        double d = 1 + hx * hx + hy * hy;
        double mn = (-hx * nx - hy * ny + nz) / d; // (m . n) / |m|, m = (-hx, -hy, 1)
        double tx = nx + hx * mn, ty = ny + hy * mn, tz = nz - mn;
        double gain = tx * nx + ty * ny + tz * nz;
        if (gain < 0.1) return;
        y[2] += (least - away) / gain * tx;
        y[3] += (least - away) / gain * ty;
    }
}
