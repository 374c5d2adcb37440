package minigolf.physics;

import minigolf.collision.Hit;

/**
 * The ball's response to the obstacle contact {@link PathSweep} found (docs/physics.md): the
 * velocity reflected about the contact normal, its normal part times the obstacle's restitution.
 * A rolling ball may fly off or settle against the obstacle; a flying ball may settle on top of
 * one, where it cannot roll, and is out.
 */
final class ObstacleContact {
    /**
     * A ball that moving obstacles touch more often than this in one stroke is caught (a ball riding
     * a turning bar's corner round and round): out of play (docs/course-format.md, "Moving obstacles").
     */
    static final int MOST_MOVING_CONTACTS = 500;

    private final BallState ball;
    private final StrokeReports reports;
    private final Hit hit;
    private final RestRule rest;
    /** The ball settled against an obstacle; null without obstacles. */
    private final Leaning lean;
    /** A hop under {@link Stroke#HOP_HEIGHT} with this course's gravity. */
    private final double hopSpeed;
    private final Bounce bounce;
    private final double gravity;
    /** The bricks' hits this stroke; null without bricks. */
    private final BrickHits bricks;

    ObstacleContact(BallState ball, StrokeReports reports, Hit hit, RestRule rest, Leaning lean, double hopSpeed,
                    double maxSpeed, double gravity, BrickHits bricks) {
        this.gravity = gravity;
        this.bricks = bricks;
        this.bounce = new Bounce(maxSpeed);
        this.ball = ball;
        this.reports = reports;
        this.hit = hit;
        this.rest = rest;
        this.lean = lean;
        this.hopSpeed = hopSpeed;
    }

    /**
     * A rolling ball at an obstacle: its velocity along the ground, (vx, vy, grad h . v), is
     * reflected about the contact normal. If it then leaves the ground faster than a 1 mm hop, it
     * flies; otherwise the part into or off the ground is dropped and it rolls on.
     */
    void whileRolling() {
        BallState b = ball;
        // A new heading: the rest rule's decision about a turn ahead was for the old one.
        rest.forget();
        if (hit.moving && caught()) return;
        if (hit.brick >= 0) bricks.hit(hit.brick);
        double wz = b.hx * b.vx + b.hy * b.vy;
        double before = Math.sqrt(b.vx * b.vx + b.vy * b.vy + wz * wz);
        bounce.off(b.vx, b.vy, wz, hit.nx, hit.ny, hit.nz, hit.restitution, hit.ux, hit.uy, hit.uz);
        b.vx = bounce.vx;
        b.vy = bounce.vy;
        wz = bounce.vz;
        double norm = Math.sqrt(1 + b.hx * b.hx + b.hy * b.hy);
        double away = (wz - b.hx * b.vx - b.hy * b.vy) / norm; // speed off the ground along its normal
        if (away > hopSpeed) {
            b.vz = wz;
            b.flying = true;
            lean.release();
            reports.event(StrokeEvent.Type.COLLISION, before, Math.sqrt(b.vx * b.vx + b.vy * b.vy + wz * wz));
            reports.event(StrokeEvent.Type.LAUNCH, Double.NaN, Double.NaN);
            return;
        }
        // Project onto the ground's tangent plane (the ground takes the normal part).
        double gx = -b.hx / norm, gy = -b.hy / norm, gz = 1 / norm;
        double into = b.vx * gx + b.vy * gy + wz * gz;
        b.vx -= into * gx;
        b.vy -= into * gy;
        if (hit.moving) {
            separate();
        } else if (lean.settles(hit.nx, hit.ny, hit.nz, b.vx, b.vy, b.pullX, b.pullY)) {
            // It settles against the obstacle (docs/physics.md): it rolls along it from here.
            b.vx = lean.vx;
            b.vy = lean.vy;
            b.x += lean.dx;
            b.y += lean.dy;
            b.sampleGround();
            b.z = b.h;
        }
        wz = b.hx * b.vx + b.hy * b.vy;
        reports.event(StrokeEvent.Type.COLLISION, before, Math.sqrt(b.vx * b.vx + b.vy * b.vy + wz * wz));
    }

    /** Counts a moving obstacle's contact; ends the stroke out when the ball is caught. */
    private boolean caught() {
        BallState b = ball;
        b.movingContact = true;
        if (++b.movingContacts <= MOST_MOVING_CONTACTS) return false;
        reports.removedFromPlay();
        return true;
    }

    /**
     * After a moving obstacle's contact, a rolling ball leaves it (relative to its surface, along the
     * normal) at least fast enough to get {@link Leaning#REACH} away before its friction and the
     * ground's pull, g (mu_k + |P|), could bring them together again: a ball that a sliding gate or
     * a turning bar pushes along hops ahead of it in millimetre bounces instead of an endless series
     * of ever smaller ones in finite time (docs/physics.md, "Moving obstacles"). The speed is added
     * along the normal's part in the ground's tangent plane; where that part is tiny (an obstacle
     * pressing the ball into the ground) nothing is added, and the ball, wedged, is crushed.
     */
    private void separate() {
        BallState b = ball;
        double wz = b.hx * b.vx + b.hy * b.vy;
        double away = (b.vx - hit.ux) * hit.nx + (b.vy - hit.uy) * hit.ny + (wz - hit.uz) * hit.nz;
        double pull = gravity * (b.muK + Math.sqrt(b.pullX * b.pullX + b.pullY * b.pullY));
        double least = Math.sqrt(2 * pull * Leaning.REACH);
        if (away >= least) return;
        // The normal's part along the ground: (tx, ty) horizontal, the ground's rise following it.
        double norm2 = 1 + b.hx * b.hx + b.hy * b.hy;
        double along = (-b.hx * hit.nx - b.hy * hit.ny + hit.nz) / norm2;
        double tx = hit.nx + b.hx * along, ty = hit.ny + b.hy * along, tz = hit.nz - along;
        double reach = tx * hit.nx + ty * hit.ny + tz * hit.nz;
        if (reach < 0.1) return;
        double lambda = (least - away) / reach;
        b.vx += lambda * tx;
        b.vy += lambda * ty;
    }

    /**
     * A flying ball at an obstacle: its velocity is reflected. Off a face turned upwards it may
     * leave slower than a 1 mm hop, whatever its speed along the face (docs/physics.md, "Flight"):
     * it settles there, cannot roll, and is out at the contact.
     */
    void inFlight() {
        BallState b = ball;
        if (hit.moving && caught()) return;
        if (hit.brick >= 0) bricks.hit(hit.brick);
        double before = Math.sqrt(b.vx * b.vx + b.vy * b.vy + b.vz * b.vz);
        double vn = b.vx * hit.nx + b.vy * hit.ny + b.vz * hit.nz;
        bounce.off(b.vx, b.vy, b.vz, hit.nx, hit.ny, hit.nz, hit.restitution, hit.ux, hit.uy, hit.uz);
        b.vx = bounce.vx;
        b.vy = bounce.vy;
        b.vz = bounce.vz;
        double after = Math.sqrt(b.vx * b.vx + b.vy * b.vy + b.vz * b.vz);
        reports.event(StrokeEvent.Type.COLLISION, before, after);
        // The speed off the face (relative to it, if it moves); a bumper's is what the cap left.
        double away = hit.moving || hit.restitution > 1
                ? (b.vx - hit.ux) * hit.nx + (b.vy - hit.uy) * hit.ny + (b.vz - hit.uz) * hit.nz
                : vn < 0 ? -vn * hit.restitution : vn;
        if (hit.nz > 0.5 && away < hopSpeed) {
            reports.finish(Outcome.OUT, b.x, b.y, b.z);
        }
    }
}
