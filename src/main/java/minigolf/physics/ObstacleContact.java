package minigolf.physics;

import minigolf.collision.Hit;

/**
 * The ball's response to the obstacle contact {@link PathSweep} found (docs/physics.md): the
 * velocity reflected about the contact normal, its normal part times the obstacle's restitution.
 * A rolling ball may fly off or settle against the obstacle; a flying ball may settle on top of
 * one, where it cannot roll, and is out.
 */
final class ObstacleContact {
    private final BallState ball;
    private final StrokeReports reports;
    private final Hit hit;
    private final RestRule rest;
    /** The ball settled against an obstacle; null without obstacles. */
    private final Leaning lean;
    /** A hop under {@link Stroke#HOP_HEIGHT} with this course's gravity. */
    private final double hopSpeed;

    ObstacleContact(BallState ball, StrokeReports reports, Hit hit, RestRule rest, Leaning lean, double hopSpeed) {
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
        double wz = b.hx * b.vx + b.hy * b.vy;
        double before = Math.sqrt(b.vx * b.vx + b.vy * b.vy + wz * wz);
        double vn = b.vx * hit.nx + b.vy * hit.ny + wz * hit.nz;
        if (vn < 0) {
            double j = (1 + hit.restitution) * vn;
            b.vx -= j * hit.nx;
            b.vy -= j * hit.ny;
            wz -= j * hit.nz;
        }
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
        if (lean.settles(hit.nx, hit.ny, hit.nz, b.vx, b.vy, b.hx, b.hy)) {
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

    /**
     * A flying ball at an obstacle: its velocity is reflected. Off a face turned upwards it may
     * leave slower than a 1 mm hop, whatever its speed along the face (docs/physics.md, "Flight"):
     * it settles there, cannot roll, and is out at the contact.
     */
    void inFlight() {
        BallState b = ball;
        double before = Math.sqrt(b.vx * b.vx + b.vy * b.vy + b.vz * b.vz);
        double vn = b.vx * hit.nx + b.vy * hit.ny + b.vz * hit.nz;
        if (vn < 0) {
            double j = (1 + hit.restitution) * vn;
            b.vx -= j * hit.nx;
            b.vy -= j * hit.ny;
            b.vz -= j * hit.nz;
        }
        double after = Math.sqrt(b.vx * b.vx + b.vy * b.vy + b.vz * b.vz);
        reports.event(StrokeEvent.Type.COLLISION, before, after);
        double away = vn < 0 ? -vn * hit.restitution : vn;
        if (hit.nz > 0.5 && away < hopSpeed) {
            reports.finish(Outcome.OUT, b.x, b.y, b.z);
        }
    }
}
