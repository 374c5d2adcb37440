package minigolf.physics;

import minigolf.collision.Hit;
import minigolf.terrain.Terrain;

/**
 * A rolling ball settled against an obstacle (docs/physics.md, "Rolling along an obstacle"): a
 * bounce off an obstacle that would carry it less than {@link #REACH} from it before the ground's
 * pull brings it back settles it there, and it rolls along the obstacle, which takes the part of
 * its acceleration that pushes into it ({@link RollingStep#leaning}). It leaves when the ground no
 * longer pulls it towards the obstacle or the obstacle is no longer within {@link #REACH}.
 * Without this a ball pressed against a wall bounced off it ever lower, an endless series, until
 * 16 contacts in one step stopped it where it was, however fast it moved along the wall.
 */
final class Leaning {
    /** How far from the obstacle a bounce may carry the ball and still settle it, and the obstacle's reach (m). */
    static final double REACH = 0.001;
    /** The ball is put this far off the obstacle when it settles (m), so that it rolls along it untouched. */
    private static final double GAP = 1e-7;
    /** Contacts whose normal is within 45 degrees of horizontal (|n_z| below this) can hold a ball. */
    private static final double MAX_NORMAL_Z = Math.sqrt(0.5);

    private final Solids solids;
    private final Terrain terrain;
    private final RollingStep rolling;
    private final double radius;
    private final double gravity;
    private final boolean complete;
    private final Hit hit = new Hit();

    /** The velocity and the position offset {@link #settles} leaves. */
    double vx, vy, dx, dy;
    /** The gradient {@link #effective} leaves. */
    double gx, gy;

    Leaning(Solids solids, Terrain terrain, RollingStep rolling, double radius, double gravity, boolean complete) {
        this.solids = solids;
        this.terrain = terrain;
        this.rolling = rolling;
        this.radius = radius;
        this.gravity = gravity;
        this.complete = complete;
    }

    boolean active() {
        return rolling.leaning;
    }

    void release() {
        rolling.leaning = false;
    }

    /**
     * After a contact with normal n that leaves a rolling ball on the ground with velocity
     * (ux, uy) on slope (hx, hy): whether it settles against the obstacle. If so the ball leans on
     * it, {@link #vx}, {@link #vy} hold its velocity without the part away from the obstacle and
     * {@link #dx}, {@link #dy} the step off it by {@link #GAP}; otherwise it is free.
     */
    boolean settles(double nx, double ny, double nz, double ux, double uy, double hx, double hy) {
        rolling.leaning = false;
        double horizontal = Math.sqrt(nx * nx + ny * ny);
        if (Math.abs(nz) >= MAX_NORMAL_Z || horizontal == 0) return false;
        double cx = nx / horizontal, cy = ny / horizontal;
        double pull = pull(cx, cy, hx, hy);
        double away = ux * cx + uy * cy;
        // A bounce that reaches less than REACH from the obstacle: away^2 / (2 pull) < REACH.
        if (!(pull > 0) || away * away >= 2 * pull * REACH) return false;
        vx = ux - away * cx;
        vy = uy - away * cy;
        dx = GAP * cx;
        dy = GAP * cy;
        rolling.leanX = cx;
        rolling.leanY = cy;
        rolling.leaning = true;
        return true;
    }

    /** Whether the ball at (x, y) on slope (hx, hy) still leans: pulled towards the obstacle, and it is within reach. */
    boolean holds(double x, double y, double hx, double hy) {
        return pull(rolling.leanX, rolling.leanY, hx, hy) > 0 && touches(x, y);
    }

    /** Whether the ball at (x, y), moved REACH towards the obstacle, would touch it. */
    boolean touches(double x, double y) {
        double ex = x - REACH * rolling.leanX, ey = y - REACH * rolling.leanY;
        if (!solids.anyStillNear(Math.min(x, ex), Math.min(y, ey), Math.max(x, ex), Math.max(y, ey))) return false;
        // Leaning is on still obstacles and gates only (a moving one pushes or leaves the ball).
        return solids.sweepStill(x, y, terrain.height(x, y) + radius, ex, ey, terrain.height(ex, ey) + radius, hit);
    }

    /**
     * The gradient the rest rule sees (into {@link #gx}, {@link #gy}): the ground's, without the
     * part that pulls the ball into the obstacle it leans on.
     */
    void effective(double hx, double hy) {
        gx = hx;
        gy = hy;
        if (!rolling.leaning) return;
        double up = hx * rolling.leanX + hy * rolling.leanY;
        if (up > 0) {
            gx -= up * rolling.leanX;
            gy -= up * rolling.leanY;
        }
    }

    /** Gravity's pull towards an obstacle of horizontal normal c: the model's g (grad h . c) / D. */
    private double pull(double cx, double cy, double hx, double hy) {
        double towards = gravity * (hx * cx + hy * cy);
        return complete ? towards / (1 + hx * hx + hy * hy) : towards;
    }
}
