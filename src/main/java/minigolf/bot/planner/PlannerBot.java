package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.CourseMaps;
import minigolf.bot.SearchBot;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.DistanceField;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.Obstacle;
import minigolf.course.HoleRule;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * Our bot, the game's default (docs/bots.md). Per stroke:
 * <ol>
 * <li>If the hole is within about a maximum-speed roll (along the water-avoiding distance):
 *     Broyden's quasi-Newton method from the physics guess straight at the hole, aimed at the middle
 *     of the success region, not its edge: the rest point on the centre (rest rule), or the ball
 *     crossing the centre at half the capture speed with no lateral miss (capture rule; probed in
 *     a world that differs only in the hole rule, confirmed in the real one).</li>
 * <li>Bank shots off walls and boxes: the hole mirrored in a face gives the line, Broyden the shot.</li>
 * <li>If that fails (water in the way): a sweep of directions around the shortest path's and the
 *     hole's direction at the physics speed for the path's length, scored on the distance field;
 *     promising rest points start Broyden again.</li>
 * <li>Two strokes: a look-ahead (does one putt hole from there?) from the search's resting probes,
 *     the stroke plan's one-putt lay-up, then a lay-up sweep at several speeds.</li>
 * <li>No hole-in-one: a lay-up chosen by the stroke plan (fewest straight putts to the hole over
 *     cells clear of water), with a look-ahead that the last lay-up really holes next; when that
 *     lay-up leaves 3 or more strokes, a sweep all round at several speeds plays the rest point
 *     nearest the hole instead (banks and curves get further than straight putts); failing all,
 *     a point along the shortest path; last, the shot resting nearest the hole.</li>
 * </ol>
 */
public final class PlannerBot extends SearchBot {
    private static final double SWEEP_STEP = Math.toRadians(4);
    private static final double SWEEP_HALF_WIDTH = Math.toRadians(120);
    /** The sweep gives up when its first this many shots (about ±48° round both directions) are all lost. */
    private static final int SWEEP_ALL_LOST = 24;
    /** The fine sweep's step near shots that hit obstacles, and how many shots it may spend per stroke. */
    private static final double FINE_STEP = Math.toRadians(0.1);
    private static final int FINE_PROBES = 400;
    /** Lay-ups tried from the hole-in-one search's resting probes, at least this far apart. */
    private static final int TWO_STROKE_TRIES = 3;
    private static final double TWO_STROKE_SPACING = 0.4;
    /** The lay-up sweep: directions this far apart all round, rolls of these fractions of the reach. */
    private static final double LAYUP_STEP = Math.toRadians(10);
    private static final double[] LAYUP_LENGTHS = {0.5, 0.8};
    private static final int LAYUP_TRIES = 6;
    /** The plan sweep's speeds, fractions of the maximum (its directions: LAYUP_STEP apart). */
    private static final double[] PLAN_SWEEP_SPEEDS = {0.3, 0.5, 0.7, 0.9};
    /** The plan sweep replaces the plan's lay-up when that leaves this many strokes or more. */
    private static final int SWEEP_STROKES_LEFT = 3;
    /** A plan-sweep shot resting this close to the hole (distance field) starts Broyden. */
    private static final double SWEEP_REFINE = 0.6;
    /**
     * Far from the hole (the plan's lay-up leaves BEAM_LEFT strokes or more) the plan sweep looks
     * one stroke further from its best BEAM rest points, at least BEAM_SPACING apart. Measured on
     * the mazes: maze-a 6 -> 5 strokes; applied closer it cost simulations and gained nothing.
     */
    private static final int BEAM = 3;
    private static final int BEAM_LEFT = 5;
    private static final double BEAM_SPACING = 1.0;
    /** Bank lines (shortest first) Broyden starts from. */
    private static final int BANK_TRIES = 4;
    private static final double BANK_FAN_STEP = Math.toRadians(1);
    private static final int BANK_FAN = 8;

    private final CourseMaps maps = new CourseMaps();
    /** Shots the look-ahead found holing from a lay-up's rest point: reused when the ball is there. */
    private final List<Solved> solved = new ArrayList<>();
    private World planWorld;
    private StrokePlan plan;
    private World probeSource;
    private World probeWorld;

    @Override
    public String name() {
        return "planner";
    }

    @Override
    protected CountingSimulator.ShotScore scoreFor(BotRequest request) {
        maps.prepare(request.world(), request.token());
        DistanceField field = maps.toHole();
        return r -> {
            if (r.outcome() == Outcome.HOLED) return -1;
            if (r.outcome().isPenalty()) return 1e9;
            double d = field.at(r.endX(), r.endY());
            return Double.isFinite(d) ? d : 1e8;
        };
    }

    @Override
    protected Shot search(BotRequest request) {
        World world = request.world();
        CountingSimulator sim = request.simulator();
        maps.prepare(world, request.token());
        for (Solved k : solved) {
            // The lay-up came to rest exactly where the look-ahead holed out from: its shot, no new simulation.
            if (k.world() == world && k.x() == request.ballX() && k.y() == request.ballY()) return k.shot();
        }
        Stroke stroke = new Stroke(solved, sim, probeFor(sim), maps, request.ballX(), request.ballY(), () -> planFor(world, request));

        double reach = stroke.maxRoll();
        double pathLength = stroke.pathLength;
        Planned planned = null;
        if (Double.isFinite(pathLength) && pathLength <= 1.3 * reach) {
            sim.phase("direct");
            Shot shot = stroke.holeInOne();
            if (shot != null) return shot;
            sim.phase("two strokes");
            shot = stroke.twoStrokes();
            if (shot != null) return shot;
            // The plan's one-putt lay-up, when the look-ahead confirms it, before the costlier sweep.
            planned = stroke.plannedLayup();
            if (planned != null && planned.verified()) return planned.shot();
            // The sweep looks for two strokes: worth it when the plan sees no lay-up or a one-putt one.
            if (planned == null || planned.strokesLeft() <= 1) {
                shot = stroke.layupSweep();
                if (shot != null) return shot;
            }
        }
        sim.phase("lay-up");
        Shot layup = stroke.layup(reach, planned);
        if (layup != null) return layup;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(world, request.ballX(), request.ballY());
    }

    private StrokePlan planFor(World world, BotRequest request) {
        if (planWorld != world) {
            plan = new StrokePlan(world, maps.grid(), request.token());
            planWorld = world;
        }
        return plan;
    }

    private CountingSimulator probeFor(CountingSimulator sim) {
        World world = sim.world();
        if (world.hole().rule() == HoleRule.REST) return sim;
        if (probeSource != world) {
            Course c = world.course();
            Hole h = c.hole();
            Course probe = new Course(c.format(), c.name(), c.terrain(), c.bounds(), c.physics(), c.start(),
                    new Hole(h.position(), h.radius(), HoleRule.REST, null), c.zones(), c.obstacles());
            probeWorld = new World(probe, world.terrain());
            probeSource = world;
        }
        return sim.variant(probeWorld, true);
    }

    /**
     * The straight faces a ball can bank off, each {x0, y0, x1, y1, nx, ny, restitution}: the face
     * moved out by the ball's radius (where the ball's centre is at contact), n pointing away from
     * the obstacle. Walls give their two long sides, boxes their four (not a box raised above a
     * rolling ball, which passes under it).
     */
    static List<double[]> bankFaces(World world) {
        double ballRadius = world.physics().ballRadius();
        List<double[]> faces = new ArrayList<>();
        for (Obstacle o : world.course().obstacles()) {
            if (o instanceof Obstacle.Wall w) {
                double dx = w.to().x() - w.from().x(), dy = w.to().y() - w.from().y(), len = Math.hypot(dx, dy);
                if (len < 1e-9) continue;
                double cx = (w.from().x() + w.to().x()) / 2, cy = (w.from().y() + w.to().y()) / 2;
                addRectangleFaces(faces, cx, cy, dx / len, dy / len, len / 2, w.thickness() / 2, ballRadius, w.restitution(), false);
            } else if (o instanceof Obstacle.Box b) {
                double cx = (b.min().x() + b.max().x()) / 2, cy = (b.min().y() + b.max().y()) / 2;
                if (b.min().z() > world.terrain().height(cx, cy) + 2 * ballRadius) continue;
                double a = Math.toRadians(b.rotationDeg());
                addRectangleFaces(faces, (b.min().x() + b.max().x()) / 2, (b.min().y() + b.max().y()) / 2,
                        Math.cos(a), Math.sin(a), (b.max().x() - b.min().x()) / 2, (b.max().y() - b.min().y()) / 2,
                        ballRadius, b.restitution(), true);
            }
        }
        return faces;
    }

    /** A rectangle centred at c with half sizes hu along u and hv across: its long sides (and ends). */
    private static void addRectangleFaces(List<double[]> faces, double cx, double cy, double ux, double uy,
                                          double hu, double hv, double r, double restitution, boolean ends) {
        double vx = -uy, vy = ux;
        for (int s : new int[] {1, -1}) {
            double ox = cx + s * (hv + r) * vx, oy = cy + s * (hv + r) * vy;
            faces.add(new double[] {ox - hu * ux, oy - hu * uy, ox + hu * ux, oy + hu * uy, s * vx, s * vy, restitution});
            if (ends) {
                double ex = cx + s * (hu + r) * ux, ey = cy + s * (hu + r) * uy;
                faces.add(new double[] {ex - hv * vx, ey - hv * vy, ex + hv * vx, ey + hv * vy, s * ux, s * uy, restitution});
            }
        }
    }

    /** The search for one stroke from one ball position. */
    private static final class Stroke {
        final CountingSimulator sim;
        final CountingSimulator probe;
        final World world;
        final CourseGrid grid;
        final DistanceField field;
        final double px, py, holeX, holeY, radius;
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
            this.holeX = world.hole().position().x();
            this.holeY = world.hole().position().y();
            this.radius = world.hole().radius();
            this.capture = world.hole().rule() == HoleRule.CAPTURE;
            this.tolerance = Math.min(0.2 * radius, 0.03);
            this.gravity = world.physics().gravity();
            double d = field.at(px, py);
            this.pathLength = Double.isFinite(d) ? d : Math.hypot(holeX - px, holeY - py);
            this.path = field.path(px, py);
        }

        /** How far a maximum-speed shot rolls on a plane through the ball and the hole. */
        double maxRoll() {
            double v = world.physics().maxSpeed();
            double mu = Math.max(world.friction().kinetic(px, py), 1e-3);
            double drop = world.terrain().height(px, py) - world.terrain().height(holeX, holeY);
            return v * v / (2 * gravity * mu) + drop / mu;
        }

        /** The look-ahead: does the straight solver hole out from here? Its shot is kept for the next stroke. */
        boolean solvedHole() {
            double hx = holeX - px, hy = holeY - py;
            Attempt a = solveHole(guess(Math.atan2(hy, hx), Math.hypot(hx, hy)), null);
            if (a.holed) solved.add(new Solved(world, px, py, a.shot));
            return a.holed;
        }

        Shot holeInOne() {
            double holeAngle = Math.atan2(holeY - py, holeX - px);
            Shot direct = guess(holeAngle, Math.hypot(holeX - px, holeY - py));
            Attempt first = solveHole(direct, null);
            if (first.holed) return first.shot;
            // Reuse: when the straight shot was lost (water on the line), the sweep's faster shot
            // along the same line is lost too; it is not probed again.
            boolean lineLost = firstEval != null && firstEval.penalty
                    && Math.abs(Math.atan2(firstEval.shot.vy(), firstEval.shot.vx()) - holeAngle) < 1e-9;
            sim.phase("bank");
            Shot bank = bankShot();
            if (bank != null) return bank;
            sim.phase("sweep");
            List<Candidate> candidates = new ArrayList<>();
            List<double[]> promising = new ArrayList<>();
            boolean obstacles = false;
            boolean reachTested = false;
            boolean pathShot = true;
            int lost = 0;
            for (double angle : sweepAngles()) {
                if (lineLost && Math.abs(Math.IEEEremainder(angle - holeAngle, 2 * Math.PI)) < 0.4 * SWEEP_STEP) continue;
                Shot shot = guess(angle, pathLength);
                Eval e = evaluate(shot, holeX, holeY);
                if (e.holed) return shot;
                obstacles |= e.collided;
                boolean firstShot = pathShot;
                pathShot = false;
                if (e.penalty) {
                    // Not one shot near the path's and the hole's directions comes to rest: water or
                    // the edge cuts every way at this speed, and the lay-up search takes over.
                    if (++lost >= SWEEP_ALL_LOST && candidates.isEmpty()) return null;
                    continue;
                }
                double d = field.at(e.restX, e.restY);
                if (!Double.isFinite(d)) continue;
                if (firstShot && lineLost && d < 0.5 * pathLength && d >= Math.max(0.6, 0.25 * pathLength)) {
                    // The sweep's first shot, along the shortest path's first leg round the water,
                    // resting on the way: the best guess there is; Broyden from it before sweeping on.
                    sim.phase("refine");
                    Attempt a = solveHole(shot, e);
                    if (a.holed) return a.shot;
                    sim.phase("sweep");
                }
                if (!reachTested && shot.speed() >= sim.maxSpeed() * 0.999) {
                    // A maximum-speed shot along the way that stops far short: the hole is out of reach.
                    reachTested = true;
                    if (d > 0.3 * pathLength && field.at(px, py) - d < 0.8 * pathLength) return null;
                }
                candidates.add(new Candidate(shot, d));
                if (d < Math.max(0.6, 0.25 * pathLength)) {
                    promising.add(new double[] {angle, d});
                    sim.phase("refine");
                    Attempt a = solveHole(shot, e);
                    if (a.holed) return a.shot;
                    sim.phase("sweep");
                }
            }
            // The best three sweep shots start Broyden once more only where shots hit obstacles: on
            // open courses they are the ones that were not promising (2 m and more off) and never
            // holed on the suite (about 40 simulations each time); among obstacles their resting
            // probes feed the lay-up choice (without them maze-a takes 6 strokes instead of 5).
            if (obstacles) {
                candidates.sort((x, y) -> Double.compare(x.distance, y.distance));
                sim.phase("refine");
                for (int i = 0; i < Math.min(3, candidates.size()); i++) {
                    Attempt a = solveHole(candidates.get(i).shot, null);
                    if (a.holed) return a.shot;
                }
            }
            return obstacles ? fineSweep(promising) : null;
        }

        /**
         * Obstacles (a tree field) leave corridors narrower than the coarse sweep's step between
         * shots that hit them: the rest point is continuous inside a corridor and jumps at its
         * edges (a shot that caroms off a trunk into the hole has one tree to hit, on one side),
         * so neither the sweep nor Broyden from its shots sees one. When some sweep shot hit an
         * obstacle: around each promising sweep shot (rest point near the hole), nearest first,
         * directions FINE_STEP apart over one coarse step either side; a shot stopping within
         * 0.6 m of the hole starts Broyden. At most FINE_PROBES shots.
         */
        Shot fineSweep(List<double[]> promising) {
            sim.phase("fine sweep");
            promising.sort((a, b) -> Double.compare(a[1], b[1]));
            List<Double> tried = new ArrayList<>();
            int probes = 0;
            for (double[] centre : promising) {
                for (int k = 1; k * FINE_STEP < SWEEP_STEP + 1e-9; k++) {
                    for (int sign : new int[] {1, -1}) {
                        double angle = centre[0] + sign * k * FINE_STEP;
                        boolean duplicate = false;
                        for (double t : tried) {
                            if (Math.abs(Math.IEEEremainder(angle - t, 2 * Math.PI)) < 0.5 * FINE_STEP) duplicate = true;
                        }
                        if (duplicate) continue;
                        tried.add(angle);
                        if (++probes > FINE_PROBES) return null;
                        Shot shot = guess(angle, pathLength);
                        Eval e = evaluate(shot, holeX, holeY);
                        if (e.holed) return shot;
                        if (e.penalty) continue;
                        double d = field.at(e.restX, e.restY);
                        if (Double.isFinite(d) && d < 0.6) {
                            sim.phase("refine");
                            Attempt a = solveHole(shot, e);
                            if (a.holed) return a.shot;
                            sim.phase("fine sweep");
                        }
                    }
                }
            }
            return null;
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
            if (!onHole.converged) return Attempt.failed(onHole.shot);
            Shot centred = centreCapture(onHole.shot);
            if (centred != null && CountingSimulator.holed(sim.simulate(px, py, centred))) {
                return new Attempt(centred, true, true, 0, null);
            }
            if (CountingSimulator.holed(sim.simulate(px, py, onHole.shot))) {
                return new Attempt(onHole.shot, true, true, onHole.miss, onHole.last);
            }
            return Attempt.failed(onHole.shot);
        }

        /**
         * From a shot that stops on the hole, the shot in the middle of the capture window: first
         * its speed scaled (secant method) until the ball crosses the centre at half the capture
         * speed, then its angle turned (secant) until it crosses with no lateral miss.
         */
        Shot centreCapture(Shot onHole) {
            double target = 0.5 * world.hole().effectiveCaptureSpeed();
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

        /**
         * No hole-in-one: two strokes if the hole can be reached that way. First the probes of the
         * hole-in-one search, which already rest in many places (over a hill, round a pool) where
         * the straight-putt plan sees no one-putt; then, if none of them does, a lay-up sweep over
         * directions and several speeds (a lay-up may need a curved shot far off the hole's line at
         * a speed the one-speed sweep never probes). Rest points are ranked by a cheap test, and
         * the best few, at least TWO_STROKE_SPACING apart, get the look-ahead: the shot is played
         * if the next stroke from its rest point holes out.
         */
        Shot twoStrokes() {
            return tryLayups(triedLayups, TWO_STROKE_TRIES, false);
        }

        /** The second half of {@link #twoStrokes}: the lay-up sweep, then the look-ahead from its best rest points. */
        Shot layupSweep() {
            sim.phase("lay-up sweep");
            double holeAngle = Math.atan2(holeY - py, holeX - px);
            double longest = Math.min(0.99 * maxRoll(), 1.1 * pathLength);
            for (int k = 0; k * LAYUP_STEP <= Math.PI + 1e-9; k++) {
                for (int sign : new int[] {1, -1}) {
                    if ((k == 0 || k * LAYUP_STEP >= Math.PI - 1e-9) && sign < 0) continue;
                    double angle = holeAngle + sign * k * LAYUP_STEP;
                    for (double fraction : LAYUP_LENGTHS) {
                        Shot s = guessLength(angle, fraction * longest);
                        if (evaluate(s, holeX, holeY).holed) return s;
                    }
                }
            }
            sim.phase("two strokes");
            return tryLayups(triedLayups, LAYUP_TRIES, true);
        }

        /**
         * Look-ahead from up to {@code tries} resting probes not near one already tried: those
         * from which a straight putt sees the hole clear of water within reach first (the cheap
         * "can I hole from here" test), each group nearest the hole on the distance field first.
         */
        Shot tryLayups(List<double[]> tried, int tries, boolean puttOnly) {
            StrokePlan p = plan.get();
            List<double[]> options = new ArrayList<>();
            for (int i = 0; i < restingProbes.size(); i++) {
                Eval e = restingProbes.get(i);
                double d = field.at(e.restX, e.restY);
                if (grid.hazardClearance(e.restX, e.restY) < StrokePlan.REST_CLEARANCE
                        || grid.clearance(e.restX, e.restY) < StrokePlan.REST_OBSTACLE_CLEARANCE
                        || !Double.isFinite(d)) continue;
                boolean putt = p.putt(e.restX, e.restY, holeX, holeY);
                if (puttOnly && !putt) continue;
                double rank = putt ? d : 1e4 + d;
                options.add(new double[] {rank, i});
            }
            options.sort((a, b) -> Double.compare(a[0], b[0]));
            int attempts = 0;
            for (double[] o : options) {
                if (attempts == tries) break;
                Eval e = restingProbes.get((int) o[1]);
                boolean near = false;
                for (double[] t : tried) near |= Math.hypot(t[0] - e.restX, t[1] - e.restY) < TWO_STROKE_SPACING;
                if (near) continue;
                tried.add(new double[] {e.restX, e.restY});
                attempts++;
                Stroke next = new Stroke(solved, sim, probe, maps, e.restX, e.restY, plan);
                if (next.solvedHole()) return e.shot;
            }
            return null;
        }

        /**
         * No hole-in-one: rest on the shortest path. The strokes still needed are split evenly, and
         * the aim is the farthest point of the path that a straight putt sees clear of water.
         */
        Shot layup(double reach, Planned known) {
            Planned planned = known != null ? known : plannedLayup();
            if (planned == null || planned.strokesLeft() >= SWEEP_STROKES_LEFT) {
                Shot further = planSweep(planned == null ? 0 : planned.strokesLeft());
                if (further != null) return further;
            }
            if (planned != null) return planned.shot();
            if (path.isEmpty()) return progressSweep();
            int strokesLeft = Math.max(2, (int) Math.ceil(pathLength / (0.99 * reach)));
            double along = Math.min(pathLength / strokesLeft, 0.99 * reach);
            for (int attempt = 0; attempt < 4; attempt++) {
                double[] w = visiblePointAlongPath(along);
                double distance = Math.hypot(w[0] - px, w[1] - py);
                Shot start = guessTo(Math.atan2(w[1] - py, w[0] - px), distance, w[0], w[1]);
                Attempt a = broydenTo(start, null, w[0], w[1], 10, Math.max(0.1, 0.05 * distance), false);
                if (a.converged) return a.shot;
                along *= 0.7;
            }
            return progressSweep();
        }

        /**
         * The lay-up the stroke plan suggests: of the cells a straight putt from the ball reaches,
         * those with the fewest strokes left, nearest the hole and clearest of water first.
         */
        Planned plannedLayup() {
            sim.phase("plan");
            StrokePlan p = plan.get();
            List<int[]> options = new ArrayList<>();
            int fewest = Integer.MAX_VALUE;
            for (int i = 0; i < p.cells(); i++) {
                int left = p.strokes(i);
                if (left == Integer.MAX_VALUE || left > fewest) continue;
                if (!p.putt(px, py, p.x(i), p.y(i))) continue;
                if (left < fewest) {
                    fewest = left;
                    options.clear();
                }
                options.add(new int[] {i});
            }
            if (options.isEmpty()) return null;
            options.sort((a, b) -> Double.compare(layupCost(p, a[0]), layupCost(p, b[0])));
            sim.phase("lay-up (" + fewest + " to go)");
            Shot firstConverged = null;
            for (int k = 0; k < Math.min(fewest == 1 ? 6 : 4, options.size()); k++) {
                int i = options.get(k)[0];
                double tx = p.x(i), ty = p.y(i);
                double distance = Math.hypot(tx - px, ty - py);
                Shot start = guessTo(Math.atan2(ty - py, tx - px), distance, tx, ty);
                Attempt a = broydenTo(start, null, tx, ty, 10, 0.5 * StrokePlan.REST_CLEARANCE, false);
                if (!a.converged) continue;
                if (fewest > 1) return new Planned(a.shot, false, fewest);
                // Look ahead: keep the lay-up from which the next stroke really holes out
                // (the straight-putt plan does not know how the hills bend the ball).
                if (firstConverged == null) firstConverged = a.shot;
                triedLayups.add(new double[] {a.last.restX, a.last.restY});
                Stroke next = new Stroke(solved, sim, probe, maps, a.last.restX, a.last.restY, plan);
                if (next.solvedHole()) {
                    return new Planned(a.shot, true, fewest);
                }
            }
            return firstConverged == null ? null : new Planned(firstConverged, false, fewest);
        }

        /**
         * The plan knows straight putts only, so far from the hole its lay-ups follow the corridors
         * one straight leg at a time, while a shot that banks off walls or curves over hills may
         * get much further. A sweep of directions all round at several speeds (fractions of the
         * maximum); of its rest points (and every other resting probe of this stroke) well clear
         * of water and a little of obstacles, the nearest the hole on the distance field is played;
         * when the plan's lay-up leaves {@code planLeft} >= BEAM_LEFT strokes, the one of the best
         * few whose own sweep rests nearest the hole. Shots resting near the hole start Broyden.
         */
        Shot planSweep(int planLeft) {
            Shot holed = sweepAllRound();
            if (holed != null) return holed;
            List<Eval> ranked = safeRests();
            if (ranked.isEmpty()) return null;
            if (planLeft < BEAM_LEFT) return ranked.get(0).shot;
            // Look one stroke further: from the best few rest points (at least BEAM_SPACING apart)
            // a sweep of their own; play the one whose best follow-up rests nearest the hole.
            sim.phase("plan look-ahead");
            List<Eval> tried = new ArrayList<>();
            Eval best = ranked.get(0);
            double bestNext = Double.POSITIVE_INFINITY;
            for (Eval e : ranked) {
                if (tried.size() == BEAM) break;
                boolean near = false;
                for (Eval t : tried) near |= Math.hypot(t.restX - e.restX, t.restY - e.restY) < BEAM_SPACING;
                if (near) continue;
                tried.add(e);
                Stroke next = new Stroke(solved, sim, probe, maps, e.restX, e.restY, plan);
                if (next.sweepAllRound() != null) return e.shot;
                List<Eval> after = next.safeRests();
                double d = after.isEmpty() ? Double.POSITIVE_INFINITY : field.at(after.get(0).restX, after.get(0).restY);
                if (d < bestNext) {
                    bestNext = d;
                    best = e;
                }
            }
            return best.shot;
        }

        /** The resting probes of this stroke well clear of water and a little of obstacles, nearest the hole first. */
        List<Eval> safeRests() {
            List<Eval> safe = new ArrayList<>();
            for (Eval e : restingProbes) {
                if (grid.hazardClearance(e.restX, e.restY) < StrokePlan.REST_CLEARANCE
                        || grid.clearance(e.restX, e.restY) < StrokePlan.REST_OBSTACLE_CLEARANCE
                        || !Double.isFinite(field.at(e.restX, e.restY))) continue;
                safe.add(e);
            }
            safe.sort((a, b) -> Double.compare(field.at(a.restX, a.restY), field.at(b.restX, b.restY)));
            return safe;
        }

        /** Directions LAYUP_STEP apart all round at the plan sweep's speeds; a shot that holes, or null. */
        Shot sweepAllRound() {
            sim.phase("plan sweep");
            double holeAngle = Math.atan2(holeY - py, holeX - px);
            for (int k = 0; k * LAYUP_STEP < 2 * Math.PI - 1e-9; k++) {
                for (double fraction : PLAN_SWEEP_SPEEDS) {
                    Shot s = sim.limit(Shot.polar(holeAngle + k * LAYUP_STEP, fraction * sim.maxSpeed()));
                    Eval e = evaluate(s, holeX, holeY);
                    if (e.holed) return s;
                    // A shot (banked, curved) resting near the hole: Broyden may hole it.
                    if (!e.penalty && field.at(e.restX, e.restY) < SWEEP_REFINE) {
                        Attempt a = solveHole(s, e);
                        if (a.holed) return a.shot;
                    }
                }
            }
            return null;
        }

        double layupCost(StrokePlan p, int i) {
            double d = field.at(p.x(i), p.y(i));
            return (Double.isFinite(d) ? d : 1e6) - Math.min(grid.hazardClearance(p.x(i), p.y(i)), 1.0)
                    - 0.3 * Math.min(grid.clearance(p.x(i), p.y(i)), 0.5);
        }

        /** The last resort: many directions and speeds, keep the rest point nearest the hole. */
        Shot progressSweep() {
            sim.phase("progress");
            double reach = Math.max(0.5, maxRoll());
            for (double angle : sweepAngles()) {
                for (double fraction : new double[] {0.35, 0.7, 1.0}) {
                    evaluate(guessLength(angle, fraction * Math.min(reach, pathLength + 1)), holeX, holeY);
                }
            }
            return sim.bestShot();
        }

        double[] pointAlongPath(double distance) {
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
            double mu = world.friction().kinetic(px, py);
            double rise = world.terrain().height(tx, ty) - world.terrain().height(px, py);
            double speedSquared = 2 * gravity * (mu * length + rise);
            double speed = Math.sqrt(Math.max(speedSquared, 0.04));
            return sim.limit(Shot.polar(angle, speed));
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
            if (e.penalty) return Attempt.failed(e.shot);
            double[] j = flatJacobian(e);
            if (mirror != null) j = reflected(j, mirror[0], mirror[1]);
            Attempt bestHoled = null;
            boolean refreshed = false;
            // The point aimed at: the hole's centre, until a step towards it is lost in water
            // (the centre's shots lie beyond the water's edge): then the part of the hole on this side.
            boolean retargeted = false;
            for (int iteration = 0; iteration < maxIterations; iteration++) {
                double fx = e.restX - tx, fy = e.restY - ty;
                double miss = Math.hypot(fx, fy);
                if (holeMode && e.holed && (bestHoled == null || miss < bestHoled.miss)) {
                    bestHoled = new Attempt(e.shot, true, true, miss, e);
                }
                if (miss < tol || (retargeted && e.holed)) {
                    if (!holeMode) return new Attempt(e.shot, false, true, miss, e);
                    if (e.holed) return bestHoled;
                    break;
                }
                double det = j[0] * j[3] - j[1] * j[2];
                if (!(Math.abs(det) > 1e-12)) break;
                double dvx = -(j[3] * fx - j[1] * fy) / det;
                double dvy = -(-j[2] * fx + j[0] * fy) / det;
                double stepCap = 0.5 * e.shot.speed() + 0.2;
                double stepLength = Math.hypot(dvx, dvy);
                if (stepLength > stepCap) {
                    dvx *= stepCap / stepLength;
                    dvy *= stepCap / stepLength;
                }
                Eval next = null;
                boolean lost = false;
                for (int halving = 0; halving < 4; halving++) {
                    Shot candidate = sim.limit(Shot.of(e.shot.vx() + dvx, e.shot.vy() + dvy));
                    Eval trial = evaluate(candidate, tx, ty);
                    if (!trial.penalty && Math.hypot(trial.restX - tx, trial.restY - ty) < miss) {
                        next = trial;
                        break;
                    }
                    if (holeMode && trial.holed && bestHoled == null) {
                        bestHoled = new Attempt(trial.shot, true, true, Math.hypot(trial.restX - tx, trial.restY - ty), trial);
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
                double sx = next.shot.vx() - e.shot.vx(), sy = next.shot.vy() - e.shot.vy();
                double s2 = sx * sx + sy * sy;
                if (s2 > 0) {
                    double yx = next.restX - e.restX - (j[0] * sx + j[1] * sy);
                    double yy = next.restY - e.restY - (j[2] * sx + j[3] * sy);
                    j[0] += yx * sx / s2;
                    j[1] += yx * sy / s2;
                    j[2] += yy * sx / s2;
                    j[3] += yy * sy / s2;
                }
                e = next;
            }
            if (bestHoled != null) return bestHoled;
            return Attempt.failed(e.shot);
        }

        /**
         * Bank shots off the straight faces of walls and boxes: the hole mirrored in a face (moved
         * out by the ball's radius) gives the direction, the bank point must lie on the face with
         * both legs clear of obstacles, and the speed comes from the energy on both legs with the
         * normal speed scaled by the restitution at the bounce. Broyden starts from there with the
         * flat Jacobian mirrored in the face (after the bounce a shot turned left ends up right).
         * The shortest few bank lines are tried.
         */
        Shot bankShot() {
            List<double[]> lines = new ArrayList<>();
            double mu = Math.max(world.friction().kinetic(px, py), 1e-3);
            for (double[] f : bankFaces(world)) {
                double nx = f[4], ny = f[5];
                double ball = (px - f[0]) * nx + (py - f[1]) * ny, hole = (holeX - f[0]) * nx + (holeY - f[1]) * ny;
                if (ball <= 0.05 || hole <= 0.05) continue;
                // The mirrored hole, and where the line to it meets the face.
                double mx = holeX - 2 * hole * nx, my = holeY - 2 * hole * ny;
                double t = ball / (ball + hole);
                double bx = px + t * (mx - px), by = py + t * (my - py);
                double fx = f[2] - f[0], fy = f[3] - f[1], faceLength = Math.hypot(fx, fy);
                double along = ((bx - f[0]) * fx + (by - f[1]) * fy) / faceLength;
                if (along < 0.05 || along > faceLength - 0.05) continue;
                double l1 = Math.hypot(bx - px, by - py), l2 = Math.hypot(holeX - bx, holeY - by);
                // Both legs clear of obstacles up to a little before the bounce (water is Broyden's business).
                double back = Math.min(0.15, 0.5 * Math.min(l1, l2));
                double ax = bx + back * nx, ay = by + back * ny;
                if (!grid.clearLine(px, py, ax, ay, 0, 0) || !grid.clearLine(ax, ay, holeX, holeY, 0, 0)) continue;
                double sinIn = ball / Math.max(Math.hypot(bx - px, by - py), 1e-9);
                double kept = (1 - sinIn * sinIn) + f[6] * f[6] * sinIn * sinIn;
                double hb = world.terrain().height(bx, by);
                double after = 2 * gravity * (mu * l2 + world.terrain().height(holeX, holeY) - hb);
                double v2 = Math.max(after, 0.01) / Math.max(kept, 0.05) + 2 * gravity * (mu * l1 + hb - world.terrain().height(px, py));
                if (v2 <= 0 || Math.sqrt(v2) > 1.05 * sim.maxSpeed()) continue;
                lines.add(new double[] {l1 + l2, Math.atan2(my - py, mx - px), Math.sqrt(v2), nx, ny});
            }
            lines.sort((a, b) -> Double.compare(a[0], b[0]));
            for (int i = 0; i < Math.min(BANK_TRIES, lines.size()); i++) {
                double[] l = lines.get(i);
                double[] mirror = {l[3], l[4]};
                // The hills bend the legs, so the geometric line may end in water: a small fan of
                // directions around it, outward from the line; a bank shot resting near the hole starts Broyden.
                int starts = 0;
                for (int k = 0; k <= BANK_FAN && starts < 2; k++) {
                    for (int sign : new int[] {1, -1}) {
                        if (k == 0 && sign < 0) continue;
                        Shot shot = sim.limit(Shot.polar(l[1] + sign * k * BANK_FAN_STEP, l[2]));
                        Eval e = evaluate(shot, holeX, holeY);
                        if (e.holed) return shot;
                        if (e.penalty || !e.collided) continue;
                        double d = field.at(e.restX, e.restY);
                        if (!(d < Math.max(1.0, 0.25 * l[0]))) continue;
                        starts++;
                        Attempt a = capture ? solveHole(shot, e)
                                : broydenTo(shot, e, holeX, holeY, 12, tolerance, true, mirror);
                        if (a.holed) return a.shot;
                        break;
                    }
                }
            }
            return null;
        }

        static boolean wet(Eval e) {
            return e.result.outcome() == Outcome.WATER;
        }

        /** J mirrored in the line with unit normal n: (I - 2 n n^T) J. */
        static double[] reflected(double[] j, double nx, double ny) {
            double r00 = 1 - 2 * nx * nx, r01 = -2 * nx * ny, r11 = 1 - 2 * ny * ny;
            return new double[] {
                r00 * j[0] + r01 * j[2], r00 * j[1] + r01 * j[3],
                r01 * j[0] + r11 * j[2], r01 * j[1] + r11 * j[3]
            };
        }

        /** d(rest point)/d(v) on flat ground: 2L/s along the shot, L/s across it. */
        double[] flatJacobian(Eval e) {
            double s = Math.max(e.shot.speed(), 1e-3);
            double ux = e.shot.vx() / s, uy = e.shot.vy() / s;
            double length = Math.max(Math.hypot(e.restX - px, e.restY - py), 0.1);
            double along = 2 * length / s, across = length / s;
            return new double[] {
                along * ux * ux + across * uy * uy, (along - across) * ux * uy,
                (along - across) * ux * uy, along * uy * uy + across * ux * ux
            };
        }

        double[] measuredJacobian(Eval e, double tx, double ty) {
            double h = 1e-3 * Math.max(1, e.shot.speed());
            Eval ex = evaluate(sim.limit(Shot.of(e.shot.vx() - h, e.shot.vy())), tx, ty);
            Eval ey = evaluate(sim.limit(Shot.of(e.shot.vx(), e.shot.vy() - h)), tx, ty);
            if (ex.penalty || ey.penalty) return null;
            double hx = e.shot.vx() - ex.shot.vx(), hy = e.shot.vy() - ey.shot.vy();
            if (hx == 0 || hy == 0) return null;
            return new double[] {(e.restX - ex.restX) / hx, (e.restX - ey.restX) / hy, (e.restY - ex.restY) / hx, (e.restY - ey.restY) / hy};
        }

        /** Simulates in the probe world; F = rest point - target. */
        Eval evaluate(Shot shot, double tx, double ty) {
            Approach approach = new Approach(holeX, holeY, px, py, shot);
            ShotResult r = probe.simulate(px, py, shot, approach);
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

    /** Where the ball's path passes nearest the hole, and its velocity there (steps interpolated). */
    private static final class Approach implements minigolf.physics.TrajectoryListener {
        final double hx, hy;
        double lastX, lastY, lastVx, lastVy;
        double best, cx, cy, cvx, cvy, dirX, dirY;
        boolean collided;

        Approach(double hx, double hy, double x0, double y0, Shot shot) {
            this.hx = hx;
            this.hy = hy;
            lastX = x0;
            lastY = y0;
            lastVx = shot.vx();
            lastVy = shot.vy();
            cx = x0;
            cy = y0;
            cvx = lastVx;
            cvy = lastVy;
            best = (x0 - hx) * (x0 - hx) + (y0 - hy) * (y0 - hy);
            double s = Math.max(Math.hypot(lastVx, lastVy), 1e-12);
            dirX = lastVx / s;
            dirY = lastVy / s;
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            double dx = x - lastX, dy = y - lastY;
            double len2 = dx * dx + dy * dy;
            double f = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((hx - lastX) * dx + (hy - lastY) * dy) / len2));
            double qx = lastX + f * dx, qy = lastY + f * dy;
            double d = (qx - hx) * (qx - hx) + (qy - hy) * (qy - hy);
            if (d < best) {
                best = d;
                cx = qx;
                cy = qy;
                cvx = lastVx + f * (vx - lastVx);
                cvy = lastVy + f * (vy - lastVy);
                if (len2 > 0) {
                    double l = Math.sqrt(len2);
                    dirX = dx / l;
                    dirY = dy / l;
                }
            }
            lastX = x;
            lastY = y;
            lastVx = vx;
            lastVy = vy;
        }

        @Override
        public void onEvent(minigolf.physics.StrokeEvent event) {
            if (event.type() == minigolf.physics.StrokeEvent.Type.COLLISION) collided = true;
        }
    }

    /** One probe: the shot, its rest point, the miss F and the direction the ball passed the hole in. */
    private record Eval(Shot shot, ShotResult result, boolean penalty, boolean holed, double restX, double restY,
                        double fx, double fy, double dirX, double dirY, boolean collided) {
    }

    /**
     * The stroke plan's lay-up; verified when the look-ahead holed out from its rest point;
     * strokesLeft: the plan's strokes from there.
     */
    private record Planned(Shot shot, boolean verified, int strokesLeft) {
    }

    /** A look-ahead's holing shot from a lay-up's rest point (the engine is deterministic). */
    private record Solved(World world, double x, double y, Shot shot) {
    }

    private record Candidate(Shot shot, double distance) {
    }

    private record Attempt(Shot shot, boolean holed, boolean converged, double miss, Eval last) {
        static Attempt failed(Shot shot) {
            return new Attempt(shot, false, false, Double.POSITIVE_INFINITY, null);
        }
    }
}
