package minigolf.physics.reference;

import minigolf.course.Hole;
import minigolf.course.PhysicsSettings;
import minigolf.physics.Outcome;
import minigolf.physics.PlayArea;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * Flight as docs/physics.md describes it, for the reference: gravity and quadratic drag
 * a = −g·ẑ − k·|v|·v, k = Cd·ρ·π·r²/(2m), integrated by the same adaptive Dormand–Prince pair on
 * (x, y, z, vx, vy, vz) with z the ball's bottom; landing (z reaching max(h, 0)) bisected on the
 * dense output; on landing out, water, the hole's capture, or a bounce off the ground's tangent
 * plane with the course's restitution (or Penner's turf model) and the impact's Coulomb friction,
 * settling into rolling when the bounce is lower than a 1 mm hop. Obstacles are hit in 3-D.
 */
final class ReferenceFlight implements DormandPrince.Rhs {
    private static final int SAMPLES = 4;
    private static final double MAX_STEP = 0.02;

    private final Terrain terrain;
    private final PlayArea area;
    private final Hole hole;
    private final double g, drag, hopSpeed, maxTime;
    private final Double restitution;
    private final DormandPrince stepper;
    private final ObstacleContact obstacles;
    private final double[] s = new double[6], probe = new double[6], sample = new double[3];

    /** Where a flight ended in rolling: (x, y, vx, vy) at time {@link #time}. */
    final double[] rolling = new double[4];
    double time;
    private boolean settled;
    long steps;
    int contacts;
    /** Contacts with moving obstacles in the stroke so far (carried in and out as contacts). */
    int movingContacts;
    /** Where the shot was played from (a caught ball is put back there). */
    double shotX, shotY;

    ReferenceFlight(World world, double maxTime, double tol) {
        PhysicsSettings physics = world.physics();
        this.terrain = world.terrain();
        this.area = world.playArea();
        this.hole = world.hole();
        this.g = physics.gravity();
        this.drag = physics.dragCoefficient() * physics.airDensity() * Math.PI * physics.ballRadius() * physics.ballRadius()
                / (2 * physics.ballMass());
        this.hopSpeed = Math.sqrt(2 * g * 1e-3);
        this.restitution = physics.groundRestitution();
        this.maxTime = maxTime;
        this.stepper = new DormandPrince(new double[] {tol, tol, tol, tol, tol, tol});
        this.obstacles = new ObstacleContact(world, stepper, true);
    }

    @Override
    public void derivative(double[] y, double[] d) {
        double speed = Math.sqrt(y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
        d[0] = y[3];
        d[1] = y[4];
        d[2] = y[5];
        d[3] = -drag * speed * y[3];
        d[4] = -drag * speed * y[4];
        d[5] = -g - drag * speed * y[5];
    }

    /**
     * Flies from the contact point (x, y, z) with velocity (vx, vy, vz) at time t. Returns the
     * stroke's end, or null when the ball settles into rolling ({@link #rolling}, {@link #time}).
     * {@link #steps} and {@link #contacts} carry the stroke's counts in and out.
     */
    /** The course clock when the stroke began (the moving obstacles' time is it plus the stroke's). */
    void clockOffset(double clock) {
        obstacles.clockOffset = clock;
    }

    ReferenceResult fly(double x, double y, double z, double vx, double vy, double vz, double t) {
        s[0] = x; s[1] = y; s[2] = z; s[3] = vx; s[4] = vy; s[5] = vz;
        double h = 1e-3;
        stepper.restart();
        while (true) {
            if (t >= maxTime) return new ReferenceResult(Outcome.TIMEOUT, s[0], s[1], t, true, "", steps);
            if (steps >= ReferenceSimulator.MAX_STEPS) return notCovered("more than " + ReferenceSimulator.MAX_STEPS + " steps", t);
            double step = Math.min(Math.min(h, MAX_STEP), maxTime - t);
            double err = stepper.attempt(this, t, s, step);
            h = DormandPrince.nextStep(step, err);
            if (err > 1) {
                if (h < 1e-15) return notCovered("step size underflow", t);
                continue;
            }
            steps++;
            double from = stepper.stepStart(), to = stepper.stepEnd();
            boolean contact = obstacles.find(from, to);
            double until = contact ? obstacles.time : to;
            double landing = firstLanding(from, until);
            if (!Double.isNaN(landing)) {
                stepper.interpolate(landing, s);
                t = landing;
                ReferenceResult end = land(t);
                if (end != null || settled) return end;
                stepper.restart();
            } else if (contact) {
                stepper.interpolate(obstacles.time, s);
                t = obstacles.time;
                if (++contacts > ReferenceSimulator.MAX_CONTACTS) {
                    return notCovered("more than " + ReferenceSimulator.MAX_CONTACTS + " obstacle contacts", t);
                }
                if (obstacles.moving && ++movingContacts > ReferenceSimulator.MOST_MOVING_CONTACTS) {
                    return new ReferenceResult(Outcome.OUT, shotX, shotY, t, true, "", steps);
                }
                double away = obstacles.reflect(s, 3);
                // Too slow to bounce off a face turned upwards (within 60° of up): it would rest on
                // the obstacle, which is unplayable there (out).
                if (obstacles.nz > 0.5 && away < hopSpeed) {
                    return new ReferenceResult(Outcome.OUT, s[0], s[1], t, true, "", steps);
                }
                stepper.restart();
            } else {
                stepper.accept(s);
                t = to;
            }
        }
    }

    /** The first time in (from, to] the ball's bottom is below max(h, 0), the point just past it; NaN if none. */
    private double firstLanding(double from, double to) {
        stepper.interpolate(from, probe);
        if (below(probe)) return Double.NaN;
        double sa = from;
        for (int i = 1; i <= SAMPLES; i++) {
            double sb = i == SAMPLES ? to : from + (to - from) * i / SAMPLES;
            if (!(sb > sa)) continue;
            stepper.interpolate(sb, probe);
            if (below(probe)) {
                double lo = sa, hi = sb;
                while (hi - lo > EventLocator.TIME_TOLERANCE) {
                    double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    stepper.interpolate(mid, probe);
                    if (below(probe)) hi = mid; else lo = mid;
                }
                return hi;
            }
            sa = sb;
        }
        return Double.NaN;
    }

    private boolean below(double[] y) {
        return y[2] < Math.max(terrain.height(y[0], y[1]), 0);
    }

    /**
     * The landing at state s: out, water, holed (an end), a bounce (null, s changed) or settling
     * into rolling (null, {@link #settled}, {@link #rolling} and {@link #time} set).
     */
    private ReferenceResult land(double t) {
        double x = s[0], y = s[1];
        settled = false;
        if (!area.contains(x, y)) return new ReferenceResult(Outcome.OUT, x, y, t, true, "", steps);
        terrain.sample(x, y, sample);
        if (sample[0] < 0) return new ReferenceResult(Outcome.WATER, x, y, t, true, "", steps);
        double ratio = Math.hypot(x - hole.position().x(), y - hole.position().y()) / hole.radius();
        if (ratio <= 1 && Math.hypot(s[3], s[4]) < hole.effectiveCaptureSpeed() * (1 - ratio * ratio)) {
            return new ReferenceResult(Outcome.HOLED, x, y, t, true, "", steps);
        }
        double hx = sample[1], hy = sample[2], norm = Math.sqrt(1 + hx * hx + hy * hy);
        double nx = -hx / norm, ny = -hy / norm, nz = 1 / norm;
        double into = -(s[3] * nx + s[4] * ny + s[5] * nz);
        double e = restitution != null ? restitution : penner(Math.min(into, 20));
        double tx = s[3] + into * nx, ty = s[4] + into * ny, tz = s[5] + into * nz;
        double tangential = Math.sqrt(tx * tx + ty * ty + tz * tz);
        if (tangential > 0) {
            // Coulomb friction of the impact; at 2/7 of the tangential speed the ball rolls without slipping.
            double keep = 1 - Math.min(0.4 * (1 + e) * into, tangential * 2 / 7) / tangential;
            tx *= keep;
            ty *= keep;
            tz *= keep;
        }
        s[2] = sample[0];
        if (e * into < hopSpeed) {
            rolling[0] = x;
            rolling[1] = y;
            rolling[2] = tx;
            rolling[3] = ty;
            time = t;
            settled = true;
            return null;
        }
        s[3] = tx + e * into * nx;
        s[4] = ty + e * into * ny;
        s[5] = tz + e * into * nz;
        return null;
    }

    /** Penner's turf restitution, "The run of a golf ball" (2002). */
    static double penner(double vn) {
        return 0.510 - 0.0375 * vn + 0.000903 * vn * vn;
    }

    private ReferenceResult notCovered(String why, double t) {
        return ReferenceResult.notCovered(why, s[0], s[1], t, steps);
    }
}
