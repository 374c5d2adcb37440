package minigolf.physics;

import minigolf.terrain.Terrain;

/**
 * Whether and when a rolling ball leaves the ground within a step (docs/physics.md, "Taking off"),
 * from the step's start state given by {@link #from}. {@link RollingPhase} launches the ball.
 */
final class TakeOff {
    /** How much lower than a free-falling ball the ground must be at a step's end for the ball to take off. */
    static final double LIFT_TOLERANCE = 1e-6;
    /** Half the span (m) of the central difference that gives the ground's curvature along v. */
    static final double CURVATURE_SPAN = 1e-5;

    private final Terrain terrain;
    private final RollingStep rolling;
    private final double gravity;
    private final double[] sample = new double[3];
    private double x, y, vx, vy, h, hx, hy, muK, fx, fy;
    private double lastX = Double.NaN, lastY = Double.NaN, lastH;

    TakeOff(Terrain terrain, RollingStep rolling, double gravity) {
        this.terrain = terrain;
        this.rolling = rolling;
        this.gravity = gravity;
    }

    /** The step's start: position, velocity, height, slope, kinetic friction and force there. */
    void from(double x, double y, double vx, double vy, double h, double hx, double hy, double muK, double fx, double fy) {
        this.fx = fx;
        this.fy = fy;
        this.x = x;
        this.y = y;
        this.vx = vx;
        this.vy = vy;
        this.h = h;
        this.hx = hx;
        this.hy = hy;
        this.muK = muK;
    }

    /**
     * Whether the ground curves away under the ball faster than gravity can bend its path in the
     * coming step: a ball thrown from here along the ground, (v, grad h . v), would be above the
     * ground after tau under gravity alone (its horizontal velocity kept). In the continuous model
     * that is v^T H v &lt; -g. A uniform slope, however steep, never launches the ball, nor does any
     * ground launch a ball at rest (the classic model's own acceleration down a steep slope, g
     * times the slope, is not a speed the ball has). A crest shorter than the step is looked for too
     * ({@link #curvesAwayWithin}).
     */
    boolean takesOff(double tau, double a1x, double a1y) {
        double tangent = h + (hx * vx + hy * vy) * tau;
        double ground = heightAt(x + vx * tau, y + vy * tau);
        if (ground < tangent - 0.5 * gravity * tau * tau - LIFT_TOLERANCE) return true;
        return tangent - ground >= 0.25 * gravity * tau * tau
                && (curvesAwayWithin(tau, a1x, a1y) || curvesAway(tau, a1x, a1y));
    }

    /**
     * Whether the ground along a step of length tau from (x, y) with velocity v curves away within
     * a quarter of the take-off threshold ({@link #takesOff}'s measure): a step that long is not
     * taken there (a short crest inside it could hide), the step control's steps of dt are.
     */
    boolean near(double x, double y, double vx, double vy, double h, double hx, double hy, double tau) {
        double tangent = h + (hx * vx + hy * vy) * tau;
        double ground = heightAt(x + vx * tau, y + vy * tau);
        return tangent - ground >= 0.125 * gravity * tau * tau;
    }

    /**
     * Whether a long step's stages saw the ground along its path so gently curved that it is
     * nowhere near {@link #near}'s measure, which then need not ask the terrain: bend is the
     * step's {@link RollingStep#stageBend}, the largest drop of the slope along v per fraction of
     * the step, so the ground falls below the tangent plane by about tau bend / 2 over the step
     * (the second-order term, as near measures it at the straight step's end); it must stay under
     * half of near's g tau^2 / 8. The ground between the stages is not seen, as near sees only
     * one point; where the stages see a bend, near decides.
     */
    boolean gentleAlong(double bend, double tau) {
        return bend < 0.125 * gravity * tau;
    }

    /**
     * The same measure against {@link #takesOff}'s: a step (of any length, on smooth ground) whose
     * stages saw the ground fall below the tangent plane by less than half of the g tau^2 / 4 from
     * which takesOff looks further (tau bend / 2 &lt; g tau^2 / 8) does not take off, and takesOff
     * need not ask the terrain. For RK4's steps the second stage lies on the straight step's
     * midpoint, where the slope's change along v measures the height's departure at its end
     * exactly on quadratic ground.
     */
    boolean staysDown(double bend, double tau) {
        return bend < 0.25 * gravity * tau;
    }

    /** The terrain's height at (qx, qy); the last point asked is remembered ({@link #near} and {@link #takesOff} ask the same). */
    private double heightAt(double qx, double qy) {
        if (qx != lastX || qy != lastY) {
            lastH = terrain.height(qx, qy);
            lastX = qx;
            lastY = qy;
        }
        return lastH;
    }

    /**
     * Whether a crest shorter than the step curves away too fast somewhere inside it: over the whole
     * step the ground may fall below the tangent plane by less than gravity's g tau^2 / 2 while a
     * short stretch of it curves away faster (the continuous criterion v^T H v &lt; -g holds there).
     * Checked, with probes of tau / 8 at the step's quarters, only where the whole step comes within
     * half of the threshold (takesOff has measured that, with the one terrain sample both need).
     */
    private boolean curvesAwayWithin(double tau, double a1x, double a1y) {
        double probe = tau / 8, tolerance = LIFT_TOLERANCE / 64;
        for (int k = 1; k <= 3; k++) {
            if (leaves(k * tau / 4, probe, tolerance, a1x, a1y)) return true;
        }
        return false;
    }

    /**
     * How long into a step of length tau that ends in the air the ball still rolls: the first
     * moment from which a ball thrown along the ground would be above it a short probe later
     * (tau / 8, with the tolerance scaled alike), by a forward scan and bisection on the rolling
     * sub-step, then the continuous criterion's moment near it ({@link #exactTime}). Without it
     * the ball would leave at the step's start, up to a step early (millimetres where it lands).
     */
    double time(double tau, double a1x, double a1y) {
        double probe = tau / 8;
        double tolerance = LIFT_TOLERANCE / 64;
        if (leaves(0, probe, tolerance, a1x, a1y)) return exactTime(tau, 0, probe, a1x, a1y);
        // At a crease (the edge of a drop) the probe leaves only from the last probe's reach
        // before it, not from beyond: scanned forward in half-probes, the first moment it leaves
        // is found, then the edge of that window by bisection.
        double onGround = 0, flying = -1;
        for (int k = 1; k <= 2 * 8; k++) {
            double at = k * tau / 16;
            if (leaves(at, probe, tolerance, a1x, a1y)) {
                flying = at;
                break;
            }
            onGround = at;
        }
        if (flying < 0) return exactTime(tau, tau, probe, a1x, a1y);
        for (int k = 0; k < 30; k++) {
            double mid = 0.5 * (onGround + flying);
            if (leaves(mid, probe, tolerance, a1x, a1y)) flying = mid; else onGround = mid;
        }
        return exactTime(tau, onGround, probe, a1x, a1y);
    }

    /**
     * The moment the continuous criterion v^T H v &lt; -g starts to hold, near the probe's
     * moment {@code found}. The probe looks a short way ahead (tau / 8), so it sees a crest's
     * edge about a third of it early: millimetres where the ball lands. Where the criterion is
     * off at found - probe and on at some moment up to found + probe (within the step), the
     * crossing between is located by bisection; otherwise the probe's moment stands.
     */
    private double exactTime(double tau, double found, double probe, double a1x, double a1y) {
        double onGround = Math.max(0, found - probe);
        if (curvesAway(onGround, a1x, a1y)) return found;
        double flying = -1;
        for (int k = 0; k <= 4; k++) {
            double at = Math.min(tau, found + 0.25 * k * probe);
            if (curvesAway(at, a1x, a1y)) {
                flying = at;
                break;
            }
            onGround = at;
        }
        if (flying < 0) return found;
        for (int k = 0; k < 40; k++) {
            double mid = 0.5 * (onGround + flying);
            if (curvesAway(mid, a1x, a1y)) flying = mid; else onGround = mid;
        }
        return onGround;
    }

    /** Whether v^T H v &lt; -g for the ball rolled for tau from the step's start (H v by a central difference of the gradient). */
    private boolean curvesAway(double tau, double a1x, double a1y) {
        double sx = x, sy = y, svx = vx, svy = vy;
        if (tau > 0) {
            rolling.from(x, y, vx, vy, hx, hy, muK, fx, fy);
            rolling.advance(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            sx = rolling.nx;
            sy = rolling.ny;
            svx = rolling.nvx;
            svy = rolling.nvy;
        }
        double speed = Math.sqrt(svx * svx + svy * svy);
        if (speed == 0) return false;
        double ux = svx / speed, uy = svy / speed, eps = CURVATURE_SPAN;
        terrain.sample(sx + eps * ux, sy + eps * uy, sample);
        double gx = sample[1], gy = sample[2];
        terrain.sample(sx - eps * ux, sy - eps * uy, sample);
        double curvature = ((gx - sample[1]) * ux + (gy - sample[2]) * uy) / (2 * eps);
        return curvature * speed * speed < -gravity;
    }

    /** Whether a ball rolled for tau from the step's start, then thrown along the ground, is above it after probe. */
    private boolean leaves(double tau, double probe, double tolerance, double a1x, double a1y) {
        double sx = x, sy = y, svx = vx, svy = vy, shx = hx, shy = hy;
        double sh = h;
        if (tau > 0) {
            rolling.from(x, y, vx, vy, hx, hy, muK, fx, fy);
            rolling.advance(tau, RollingStep.Kind.INTEGRATOR, a1x, a1y);
            terrain.sample(rolling.nx, rolling.ny, sample);
            sx = rolling.nx;
            sy = rolling.ny;
            svx = rolling.nvx;
            svy = rolling.nvy;
            sh = sample[0];
            shx = sample[1];
            shy = sample[2];
        }
        double free = sh + (shx * svx + shy * svy) * probe - 0.5 * gravity * probe * probe;
        return terrain.height(sx + svx * probe, sy + svy * probe) < free - tolerance;
    }

}
