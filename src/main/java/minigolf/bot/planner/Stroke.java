package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import java.util.function.BiPredicate;
import java.util.function.BooleanSupplier;
import java.util.function.Function;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.map.DistanceField;
import minigolf.bot.search.SpeedGuess;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;

/**
 * The search for one stroke from one ball position: what every stage shares (the ball, the hole,
 * the maps, the probes so far) and the tools they use: probing a shot ({@link #evaluate}), the
 * physics guesses, Broyden's method towards a point, the hole-in-one solver ({@link #solveHole})
 * and the directions to sweep. The stages are {@link HoleInOne}, {@link TwoStrokes} and {@link Layup}.
 */
final class Stroke {
    /** The hole-in-one sweep's step and half width round its two directions (also the progress sweep's). */
    static final double SWEEP_STEP = Math.toRadians(4);
    static final double SWEEP_HALF_WIDTH = Math.toRadians(120);
    /** Directions this far apart all round: the lay-up sweep and the plan sweep. */
    static final double LAYUP_STEP = Math.toRadians(10);

    final CountingSimulator sim;
    final CountingSimulator probe;
    final World world;
    final CourseGrid grid;
    final DistanceField field;
    /** The ball, and the hole this stroke plays for (the nearest on a course with several). */
    final double px, py, holeX, holeY, radius, captureSpeed;
    final boolean capture;
    final double tolerance;
    final double pathLength;
    final List<double[]> path;
    final double gravity;
    final java.util.function.Supplier<StrokePlan> plan;

    final CourseMaps maps;
    final List<Solved> solved;
    /** Every probe from this ball position that came to rest: lay-ups the plan does not know. */
    final List<Eval> restingProbes = new ArrayList<>();
    /** This stroke's first probe (null before any). */
    Eval firstEval;
    /** Rest points the two-stroke look-ahead has started from. */
    final List<double[]> triedLayups = new ArrayList<>();

    Stroke(List<Solved> solved, CountingSimulator sim, CountingSimulator probe, CourseMaps maps, double px, double py,
           java.util.function.Supplier<StrokePlan> plan) {
        this.solved = solved;
        this.plan = plan;
        this.maps = maps;
        this.sim = sim;
        this.probe = probe;
        this.world = sim.world();
        this.grid = maps.grid();
        this.field = maps.toHole();
        this.px = px;
        this.py = py;
        this.path = field.path(px, py);
        // The hole this stroke plays for: where the field's path ends (the nearest hole along the ground).
        double[] end = path.isEmpty() ? new double[] {px, py} : path.get(path.size() - 1);
        Hole target = world.nearestHole(end[0], end[1]);
        this.holeX = target.position().x();
        this.holeY = target.position().y();
        this.radius = target.radius();
        this.capture = target.rule() == HoleRule.CAPTURE;
        this.captureSpeed = target.effectiveCaptureSpeed();
        this.tolerance = Math.min(0.2 * radius, 0.03);
        this.gravity = world.physics().gravity();
        double d = field.at(px, py);
        this.pathLength = Double.isFinite(d) ? d : Math.hypot(holeX - px, holeY - py);
    }

    /** How far a maximum-speed shot rolls on a plane through the ball and the hole. */
    double maxRoll() {
        return SpeedGuess.maxRoll(world, px, py, holeX, holeY);
    }

    /** The look-ahead: does the straight solver hole out from here? Its shot is kept for the next stroke. */
    boolean solvedHole() {
        double hx = holeX - px, hy = holeY - py;
        Attempt a = solveHole(guess(Math.atan2(hy, hx), Math.hypot(hx, hy)), null);
        if (a.holed()) solved.add(new Solved(world, px, py, a.shot()));
        return a.holed();
    }

    /**
     * A shot that holes out, aimed at the middle of the success region. Rest rule: the rest
     * point on the hole's centre. Capture rule: first the rest point onto the hole, then moved
     * on past it along the line of arrival so the ball crosses the centre at half the capture
     * speed; confirmed in the real world.
     */
    Attempt solveHole(Shot start, Eval known) {
        if (!capture) return broydenTo(start, known, holeX, holeY, 12, tolerance, true);
        // Straight for the middle of the capture window; if that does not converge, first
        // bring the rest point onto the hole and centre from there.
        Shot quick = centreCapture(start);
        if (quick != null && CountingSimulator.holed(sim.simulate(px, py, quick))) {
            return new Attempt(quick, true, true, 0, null);
        }
        Attempt onHole = broydenTo(start, known, holeX, holeY, 12, 0.5 * radius, false);
        if (!onHole.converged()) return Attempt.failed(onHole.shot());
        Shot centred = centreCapture(onHole.shot());
        if (centred != null && CountingSimulator.holed(sim.simulate(px, py, centred))) {
            return new Attempt(centred, true, true, 0, null);
        }
        if (CountingSimulator.holed(sim.simulate(px, py, onHole.shot()))) {
            return new Attempt(onHole.shot(), true, true, onHole.miss(), onHole.last());
        }
        return Attempt.failed(onHole.shot());
    }

    /**
     * From a shot that stops on the hole, the shot in the middle of the capture window: first
     * its speed scaled (secant method) until the ball crosses the centre at half the capture
     * speed, then its angle turned (secant) until it crosses with no lateral miss.
     */
    Shot centreCapture(Shot onHole) {
        double target = 0.5 * captureSpeed;
        double speed = onHole.speed(), angle = Math.atan2(onHole.vy(), onHole.vx());
        // Start from the energy estimate of the extra speed, then Broyden on (speed, angle).
        speed = Math.min(Math.sqrt(speed * speed + target * target), sim.maxSpeed());
        double[] f = scaledCrossing(speed, angle, target);
        if (f == null) return null;
        double ds = 0.01 * speed, da = 0.002;
        double[] fs = scaledCrossing(speed + ds, angle, target), fa = scaledCrossing(speed, angle + da, target);
        if (fs == null || fa == null) return null;
        double[] j = {(fs[0] - f[0]) / ds, (fa[0] - f[0]) / da, (fs[1] - f[1]) / ds, (fa[1] - f[1]) / da};
        for (int i = 0; i < 8; i++) {
            if (Math.abs(f[0]) < 0.1 && Math.abs(f[1]) < 0.2) return sim.limit(Shot.polar(angle, speed));
            double det = j[0] * j[3] - j[1] * j[2];
            if (!(Math.abs(det) > 1e-12)) return null;
            double stepS = -(j[3] * f[0] - j[1] * f[1]) / det;
            double stepA = -(-j[2] * f[0] + j[0] * f[1]) / det;
            stepS = Math.max(-0.3, Math.min(0.3, stepS));
            stepA = Math.max(-0.05, Math.min(0.05, stepA));
            double newSpeed = Math.min(speed + stepS, sim.maxSpeed());
            double[] g = scaledCrossing(newSpeed, angle + stepA, target);
            if (g == null) return null;
            double sS = newSpeed - speed, sA = stepA, s2 = sS * sS + sA * sA;
            if (s2 == 0) return null;
            double yx = g[0] - f[0] - (j[0] * sS + j[1] * sA), yy = g[1] - f[1] - (j[2] * sS + j[3] * sA);
            j[0] += yx * sS / s2;
            j[1] += yx * sA / s2;
            j[2] += yy * sS / s2;
            j[3] += yy * sA / s2;
            speed = newSpeed;
            angle += stepA;
            f = g;
        }
        return null;
    }

    /** {@link #crossing} scaled: speed error in units of the target speed, lateral miss in hole radii. */
    double[] scaledCrossing(double speed, double angle, double target) {
        double[] c = crossing(Shot.polar(angle, speed), target);
        if (Double.isNaN(c[0])) return null;
        return new double[] {c[0] / target, c[1] / radius};
    }

    /**
     * Probes the shot: {speed at the closest approach - target, signed lateral miss there},
     * NaN when the ball was lost before reaching the hole.
     */
    double[] crossing(Shot shot, double target) {
        Approach approach = new Approach(holeX, holeY, px, py, shot);
        ShotResult r = probe.simulate(px, py, sim.limit(shot), approach);
        // Lost before passing the hole (its nearest point is where it was lost): no crossing.
        boolean lost = (r.outcome().isPenalty() || r.outcome() == Outcome.TIMEOUT)
                && Math.hypot(approach.cx - r.endX(), approach.cy - r.endY()) < 1e-6;
        if (lost) return new double[] {Double.NaN, Double.NaN};
        double lateral = approach.dirX * (approach.cy - holeY) - approach.dirY * (approach.cx - holeX);
        return new double[] {Math.hypot(approach.cvx, approach.cvy) - target, lateral};
    }

    /** The point {@code distance} along the shortest path; the hole when no path reaches it (cut off). */
    double[] pointAlongPath(double distance) {
        if (path.isEmpty()) return new double[] {holeX, holeY};
        double travelled = 0;
        for (int i = 1; i < path.size(); i++) {
            double[] a = path.get(i - 1), b = path.get(i);
            double seg = Math.hypot(b[0] - a[0], b[1] - a[1]);
            if (travelled + seg >= distance && seg > 0) {
                double f = (distance - travelled) / seg;
                return new double[] {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])};
            }
            travelled += seg;
        }
        return path.get(path.size() - 1);
    }

    /** The point {@code distance} along the path, pulled back until the ball sees it clearly. */
    double[] visiblePointAlongPath(double distance) {
        for (double d = distance; d > 0.2; d -= 0.1) {
            double[] p = pointAlongPath(d);
            if (grid.clearLine(px, py, p[0], p[1], 0.1, StrokePlan.LINE_OBSTACLE_CLEARANCE)) return p;
        }
        return pointAlongPath(Math.min(distance, 0.2));
    }

    /** Directions to sweep, nearest the path's first leg and the hole's direction first. */
    List<Double> sweepAngles() {
        double[] lead = pointAlongPath(Math.min(1.5, 0.5 * pathLength));
        double pathAngle = Math.atan2(lead[1] - py, lead[0] - px);
        double holeAngle = Math.atan2(holeY - py, holeX - px);
        List<Double> angles = new ArrayList<>();
        for (int k = 0; k * SWEEP_STEP <= SWEEP_HALF_WIDTH; k++) {
            for (double base : new double[] {pathAngle, holeAngle}) {
                for (int sign : new int[] {1, -1}) {
                    if (k == 0 && sign < 0) continue;
                    double a = base + sign * k * SWEEP_STEP;
                    boolean duplicate = false;
                    for (double b : angles) {
                        if (Math.abs(Math.IEEEremainder(a - b, 2 * Math.PI)) < 0.4 * SWEEP_STEP) duplicate = true;
                    }
                    if (!duplicate) angles.add(a);
                }
            }
        }
        return angles;
    }

    /** The shot in direction angle whose speed would stop the ball {@code length} along, ending at the hole's height. */
    Shot guess(double angle, double length) {
        return guessTo(angle, length, holeX, holeY);
    }

    Shot guessLength(double angle, double length) {
        return guessTo(angle, length, px, py);
    }

    /** v^2 / 2 = g (mu_k L + h_target - h_ball): energy on a path of length L. */
    Shot guessTo(double angle, double length, double tx, double ty) {
        return sim.limit(Shot.polar(angle, SpeedGuess.speed(world, px, py, length, tx, ty, 0.04)));
    }

    /**
     * Broyden's method on F(v) = rest point - (tx, ty), from {@code start} (whose evaluation
     * may be {@code known}). With {@code holeMode} (rest rule) a holed shot nearest the centre
     * is kept and returned once the miss is within {@code tol}.
     */
    Attempt broydenTo(Shot start, Eval known, double tx, double ty, int maxIterations, double tol, boolean holeMode) {
        return broydenTo(start, known, tx, ty, maxIterations, tol, holeMode, null);
    }

    /** As above, from the Jacobian {@code mirror} reflects (null: none) instead of flat ground's. */
    Attempt broydenTo(Shot start, Eval known, double tx, double ty, int maxIterations, double tol, boolean holeMode,
                      double[] mirror) {
        Eval e = known != null ? known : evaluate(sim.limit(start), tx, ty);
        if (e.penalty()) return Attempt.failed(e.shot());
        double[] j = flatJacobian(e);
        if (mirror != null) j = Jacobians.reflected(j, mirror[0], mirror[1]);
        return broydenFrom(e, j, tx, ty, maxIterations, tol, holeMode);
    }

    /**
     * A putt off cushions the map ({@link OnePuttMap}) suggests: each cushion mirrors the flat
     * Jacobian in a face the solver does not know, so it starts from the Jacobian measured by
     * forward differences (two shots) instead.
     */
    Attempt solveBanked(Shot start) {
        Eval e = evaluate(sim.limit(start), holeX, holeY);
        if (e.holed()) return new Attempt(e.shot(), true, true, 0, e);
        if (e.penalty()) return Attempt.failed(e.shot());
        double[] j = measuredJacobian(e, holeX, holeY);
        if (j == null) return Attempt.failed(e.shot());
        return broydenFrom(e, j, holeX, holeY, 12, tolerance, true);
    }

    private Attempt broydenFrom(Eval e, double[] j, double tx, double ty, int maxIterations, double tol, boolean holeMode) {
        Attempt bestHoled = null;
        boolean refreshed = false;
        // The point aimed at: the hole's centre, until a step towards it is lost in water
        // (the centre's shots lie beyond the water's edge): then the part of the hole on this side.
        boolean retargeted = false;
        for (int iteration = 0; iteration < maxIterations; iteration++) {
            double fx = e.restX() - tx, fy = e.restY() - ty;
            double miss = Math.hypot(fx, fy);
            if (holeMode && e.holed() && (bestHoled == null || miss < bestHoled.miss())) {
                bestHoled = new Attempt(e.shot(), true, true, miss, e);
            }
            if (miss < tol || (retargeted && e.holed())) {
                if (!holeMode) return new Attempt(e.shot(), false, true, miss, e);
                if (e.holed()) return bestHoled;
                break;
            }
            double det = j[0] * j[3] - j[1] * j[2];
            if (!(Math.abs(det) > 1e-12)) break;
            double dvx = -(j[3] * fx - j[1] * fy) / det;
            double dvy = -(-j[2] * fx + j[0] * fy) / det;
            double stepCap = 0.5 * e.shot().speed() + 0.2;
            double stepLength = Math.hypot(dvx, dvy);
            if (stepLength > stepCap) {
                dvx *= stepCap / stepLength;
                dvy *= stepCap / stepLength;
            }
            Eval next = null;
            boolean lost = false;
            for (int halving = 0; halving < 4; halving++) {
                Shot candidate = sim.limit(Shot.of(e.shot().vx() + dvx, e.shot().vy() + dvy));
                Eval trial = evaluate(candidate, tx, ty);
                if (!trial.penalty() && Math.hypot(trial.restX() - tx, trial.restY() - ty) < miss) {
                    next = trial;
                    break;
                }
                if (holeMode && trial.holed() && bestHoled == null) {
                    bestHoled = new Attempt(trial.shot(), true, true, Math.hypot(trial.restX() - tx, trial.restY() - ty), trial);
                }
                if (wet(trial) && holeMode && !retargeted && miss > 0.5 * radius) {
                    // Aim at the near side of the hole instead, half a radius from the centre.
                    retargeted = true;
                    lost = true;
                    tx = holeX + 0.5 * radius * fx / miss;
                    ty = holeY + 0.5 * radius * fy / miss;
                    break;
                }
                if (wet(trial) && bestHoled != null) return bestHoled;
                dvx *= 0.5;
                dvy *= 0.5;
            }
            if (lost) continue;
            if (next == null) {
                if (refreshed) break;
                // Broyden's model went stale: measure the Jacobian once by forward differences.
                j = measuredJacobian(e, tx, ty);
                if (j == null) break;
                refreshed = true;
                continue;
            }
            double sx = next.shot().vx() - e.shot().vx(), sy = next.shot().vy() - e.shot().vy();
            double s2 = sx * sx + sy * sy;
            if (s2 > 0) {
                double yx = next.restX() - e.restX() - (j[0] * sx + j[1] * sy);
                double yy = next.restY() - e.restY() - (j[2] * sx + j[3] * sy);
                j[0] += yx * sx / s2;
                j[1] += yx * sy / s2;
                j[2] += yy * sx / s2;
                j[3] += yy * sy / s2;
            }
            e = next;
        }
        if (bestHoled != null) return bestHoled;
        return Attempt.failed(e.shot());
    }

    static boolean wet(Eval e) {
        return e.result().outcome() == Outcome.WATER;
    }

    /** d(rest point)/d(v) on flat ground for the probe e from the ball. */
    double[] flatJacobian(Eval e) {
        return Jacobians.flat(e.shot(), e.restX() - px, e.restY() - py);
    }

    double[] measuredJacobian(Eval e, double tx, double ty) {
        double h = 1e-3 * Math.max(1, e.shot().speed());
        Eval ex = evaluate(sim.limit(Shot.of(e.shot().vx() - h, e.shot().vy())), tx, ty);
        Eval ey = evaluate(sim.limit(Shot.of(e.shot().vx(), e.shot().vy() - h)), tx, ty);
        if (ex.penalty() || ey.penalty()) return null;
        double hx = e.shot().vx() - ex.shot().vx(), hy = e.shot().vy() - ey.shot().vy();
        if (hx == 0 || hy == 0) return null;
        return new double[] {(e.restX() - ex.restX()) / hx, (e.restX() - ey.restX()) / hy, (e.restY() - ex.restY()) / hx, (e.restY() - ey.restY()) / hy};
    }

    /** One listener passing every step and event on to two. */
    static TrajectoryListener both(TrajectoryListener a, TrajectoryListener b) {
        return new TrajectoryListener() {
            @Override
            public void onStep(double t, double x, double y, double vx, double vy) {
                a.onStep(t, x, y, vx, vy);
                b.onStep(t, x, y, vx, vy);
            }

            @Override
            public void onEvent(minigolf.physics.StrokeEvent event) {
                a.onEvent(event);
                b.onEvent(event);
            }
        };
    }

    /** Simulates in the probe world; F = rest point - target. */
    Eval evaluate(Shot shot, double tx, double ty) {
        return evaluate(shot, tx, ty, null);
    }

    /** {@link #evaluate} aimed at the hole, the path also passed to {@code extra}. */
    Eval evaluateWith(Shot shot, TrajectoryListener extra) {
        return evaluate(shot, holeX, holeY, extra);
    }

    private Eval evaluate(Shot shot, double tx, double ty, TrajectoryListener extra) {
        Approach approach = new Approach(holeX, holeY, px, py, shot);
        TrajectoryListener listener = extra == null ? approach : both(approach, extra);
        return evalOf(shot, tx, ty, approach, probe.simulate(px, py, shot, listener));
    }

    /** One shot of {@link #evaluateInOrder}: the caller's trial, its shot and the listeners of its path. */
    private record Probe<T>(T trial, Shot shot, Approach approach, TrajectoryListener listener) {
    }

    /**
     * {@link #evaluateWith} for each trial in turn (its shot {@code shotOf}, its path also to
     * {@code extraOf}'s listener, its own), until {@code stopsAt} says so or {@code mayGoOn} says
     * no before a trial (as a loop's bounds): the same counts, probes and choices as that loop, the
     * shots spread over the simulator's threads ({@link CountingSimulator#simulateInOrder}). The
     * trial that ended it, or null.
     */
    <T> T evaluateInOrder(List<T> trials, Function<T, Shot> shotOf, Function<T, TrajectoryListener> extraOf,
                          BooleanSupplier mayGoOn, BiPredicate<T, Eval> stopsAt) {
        List<Probe<T>> probes = new ArrayList<>(trials.size());
        for (T t : trials) {
            Shot shot = shotOf.apply(t);
            Approach approach = new Approach(holeX, holeY, px, py, shot);
            TrajectoryListener extra = extraOf.apply(t);
            probes.add(new Probe<>(t, shot, approach, extra == null ? approach : both(approach, extra)));
        }
        Probe<T> last = probe.simulateInOrder(px, py, probes, new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Probe<T> p) {
                return p.shot();
            }

            @Override
            public TrajectoryListener listener(Probe<T> p) {
                return p.listener();
            }

            @Override
            public boolean mayGoOn() {
                return mayGoOn.getAsBoolean();
            }

            @Override
            public boolean stopsAt(Probe<T> p, ShotResult r) {
                return stopsAt.test(p.trial(), evalOf(p.shot(), holeX, holeY, p.approach(), r));
            }
        });
        return last == null ? null : last.trial();
    }

    /** The probe's evaluation from its result and where its path passed the hole; kept among this stroke's probes. */
    private Eval evalOf(Shot shot, double tx, double ty, Approach approach, ShotResult r) {
        boolean holed = !capture && r.outcome() == Outcome.HOLED;
        boolean penalty = r.outcome().isPenalty() || r.outcome() == Outcome.TIMEOUT;
        double dirX = capture ? approach.dirX : 0, dirY = capture ? approach.dirY : 0;
        Eval e = new Eval(shot, r, penalty, holed, r.endX(), r.endY(),
                penalty ? 0 : r.endX() - tx, penalty ? 0 : r.endY() - ty, dirX, dirY, approach.collided);
        if (r.outcome() == Outcome.STOPPED) restingProbes.add(e);
        if (firstEval == null) firstEval = e;
        return e;
    }
}
