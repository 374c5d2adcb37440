package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Shot;
import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;

/**
 * Two strokes chosen by where one putt holes from ({@link OnePuttMap}), not by the path distance
 * ({@code planner-aces}). Shots all round: on the first stroke those of {@link DenseSweep} (which
 * passes its paths here through {@link #tracer}), later its own sweep, {@link #STEP} apart at the
 * maximum speed (on hills also at the other {@link #HILL_SPEEDS}). Each path is traced through the
 * map; where it crosses marked cells well clear of water and obstacles (a run of them), the shot
 * slowed to stop in the middle of the run is a lay-up (its speed² worked out forwards from what
 * the sweep shot lost on the way, each cushion's share kept: exact on flat ground). Lay-ups are
 * ranked by how much error their landing forgives (the run's length, the marked cells round it)
 * and how easy the putt is; the best {@link #TRIES} (at least {@link #SPACING} apart) are played,
 * and from each rest point the map's putt starts Broyden (the look-ahead: off cushions from the
 * measured Jacobian); the first lay-up from which it holes is the shot, its putt kept for the next
 * stroke. A holed sweep shot is a hole-in-one.
 */
final class MapTwoStrokes {
    static final double STEP = Math.toRadians(1);
    /** Its own sweep's speeds on hills, fractions of the maximum (on flat ground the maximum only). */
    static final double[] HILL_SPEEDS = {1, 0.6};
    static final int TRIES = 14;
    static final int EXACT_TRIES = 6;
    /** Lay-ups whose rest points get the deep look-ahead ({@link #deepLookAhead}). */
    static final int DEEP = 3;
    static final double SPACING = 0.3;
    /** A run of marked cells longer than this forgives as much as any. */
    static final double LONG_RUN = 1.0;

    /** A lay-up: the shot that stops there, the point, how forgiving and how easy. */
    record Target(Shot shot, double x, double y, double score) {
    }

    private final Stroke s;
    private final OnePuttMap map;
    private final List<Target> targets = new ArrayList<>();
    /** Sweep shots resting in marked cells: tried after the lay-ups, at most {@link #EXACT_TRIES}. */
    private final List<Target> exact = new ArrayList<>();
    private boolean swept;
    /** Lay-ups played by {@link #search} whose look-ahead found no putt, in the order tried. */
    private final List<Eval> played = new ArrayList<>();

    MapTwoStrokes(Stroke s, OnePuttMap map) {
        this.s = s;
        this.map = map;
    }

    /** A listener collecting the lay-up targets along {@code shot}'s path (another stage's sweep). */
    Runs tracer(Shot shot) {
        return new Runs(shot);
    }

    /** Whether another stage's sweep collected the lay-up targets ({@link #search} sweeps no more). */
    boolean hasTargets() {
        return swept;
    }

    /** The lay-up targets are collected: {@link #search} sweeps no more. */
    void swept() {
        swept = true;
    }

    /** The best (lowest) score of the lay-up targets collected so far; +infinity when none. */
    double bestScore() {
        double best = Double.POSITIVE_INFINITY;
        for (Target t : targets) best = Math.min(best, t.score());
        for (Target t : exact) best = Math.min(best, t.score());
        return best;
    }

    Shot search() {
        s.sim.phase("one-putt map lay-ups");
        if (!swept) {
            boolean flat = Flatness.isFlat(s.world);
            double[] speeds = flat ? new double[] {1} : HILL_SPEEDS;
            double vMax = s.sim.maxSpeed() * (1 - 1e-9);
            int directions = (int) Math.round(2 * Math.PI / STEP);
            double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
            List<Runs> sweep = new ArrayList<>();
            for (int i = 0; i < directions; i++) {
                double angle = holeAngle + (i % 2 == 0 ? 1 : -1) * ((i + 1) / 2) * STEP;
                for (double f : speeds) sweep.add(new Runs(s.sim.limit(Shot.polar(angle, f * vMax))));
            }
            Runs holed = s.evaluateInOrder(sweep, Runs::shot, runs -> runs, () -> true, (runs, e) -> {
                if (e.holed()) return true;
                runs.end(e.result());
                return false;
            });
            if (holed != null) return holed.shot();
        }
        targets.sort((a, b) -> Double.compare(a.score(), b.score()));
        exact.sort((a, b) -> Double.compare(a.score(), b.score()));
        s.sim.phase("one-putt look-ahead");
        List<double[]> tried = new ArrayList<>();
        List<Target> order = new ArrayList<>(targets);
        order.addAll(exact);
        int exactTried = 0;
        for (Target t : order) {
            boolean isExact = exact.contains(t);
            if (!isExact && tried.size() >= TRIES) continue;
            if (isExact && exactTried >= EXACT_TRIES) break;
            boolean near = false;
            for (double[] p : tried) near |= Math.hypot(p[0] - t.x(), p[1] - t.y()) < SPACING;
            if (near) continue;
            tried.add(new double[] {t.x(), t.y()});
            if (isExact) exactTried++;
            Eval e = s.evaluate(t.shot(), s.holeX, s.holeY);
            if (e.holed()) return t.shot();
            if (e.penalty()) continue;
            if (lookAhead(e.restX(), e.restY())) return t.shot();
            played.add(e);
        }
        return null;
    }

    /**
     * The last two-stroke search: from the rest points of {@code count} lay-ups played whose
     * look-ahead failed, those where the map knows the easiest putt first, a dense hole-in-one
     * sweep ({@link DenseSweep}). The map's one putt per cell is a guess that breaks where a putt
     * flies off a rim, glances off a wall's end or crosses sand at near the speed limit; the
     * sweep from the real rest point finds such putts where they are not a fluke of one point.
     * The holing putt is kept for the next stroke; the lay-up is the shot. Null when none holes.
     */
    Shot deepLookAhead(int count) {
        s.sim.phase("deep look-ahead");
        List<Eval> order = new ArrayList<>(played);
        // The easiest putt the map knows first (a stable sort: the lay-ups' own order breaks ties).
        order.sort((a, b) -> Double.compare(map.cost(a.restX(), a.restY()), map.cost(b.restX(), b.restY())));
        for (int i = 0; i < Math.min(count, order.size()); i++) {
            Eval e = order.get(i);
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, e.restX(), e.restY(), s.plan);
            Shot putt = new DenseSweep(next).holeInOne();
            if (putt != null) {
                s.solved.add(new Solved(s.world, e.restX(), e.restY(), putt));
                return e.shot();
            }
        }
        return null;
    }

    /**
     * Whether one putt holes from (x, y): Broyden from the map's putt there (off cushions from
     * the measured Jacobian), else from the straight one; the holing putt is kept for the next stroke.
     */
    boolean lookAhead(double x, double y) {
        Shot guess = map.putt(x, y);
        Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, x, y, s.plan);
        if (guess != null) {
            int cushions = map.cushions(x, y);
            Attempt a = cushions == 0 || next.capture ? next.solveHole(s.sim.limit(guess), null)
                    : next.solveBanked(guess);
            if (a.holed()) {
                s.solved.add(new Solved(s.world, x, y, a.shot()));
                return true;
            }
            if (cushions == 0) return false;
        }
        return next.solvedHole();
    }

    /** The runs of marked cells along one shot's path, each a lay-up target. */
    final class Runs implements TrajectoryListener {
        private final Shot shot;
        private final double v0;
        private double lastX, lastY, length;
        /** The speed² a shot in this direction needs to stop at each point of the path. */
        private final StoppingNeed need;
        private int hits;
        /** The current run: its points' path lengths, positions, speeds² needed, cushions. */
        private final List<double[]> run = new ArrayList<>();
        /**
         * The lay-ups found along the path so far: kept here while the shot runs (perhaps on another
         * thread, see {@link minigolf.bot.CountingSimulator#simulateInOrder}) and added to the targets
         * at {@link #end}, in the shots' order.
         */
        private final List<Target> found = new ArrayList<>();

        /** The shot whose path this traces. */
        Shot shot() {
            return shot;
        }

        Runs(Shot shot) {
            this.shot = shot;
            this.v0 = shot.speed();
            lastX = s.px;
            lastY = s.py;
            need = new StoppingNeed(v0);
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            length += Math.hypot(x - lastX, y - lastY);
            lastX = x;
            lastY = y;
            double needHere = need.step(vx * vx + vy * vy);
            boolean in = map.marked(x, y) && s.grid.hazardClearance(x, y) >= StrokePlan.REST_CLEARANCE
                    && s.grid.clearance(x, y) >= StrokePlan.REST_OBSTACLE_CLEARANCE;
            if (in) {
                run.add(new double[] {length, x, y, needHere, hits});
            } else {
                close();
            }
        }

        @Override
        public void onEvent(StrokeEvent event) {
            if (event.type() == StrokeEvent.Type.COLLISION) {
                hits++;
                need.cushion(event.speedBefore(), event.speedAfter());
                close();
            }
        }

        /**
         * The shot is over: the current run ends, and where the shot itself came to rest is a
         * target too when the map marks it (clear of water and obstacles): a landing known exactly,
         * as forgiving as any.
         */
        void end(minigolf.physics.ShotResult r) {
            close();
            targets.addAll(found);
            found.clear();
            if (r.outcome() != minigolf.physics.Outcome.STOPPED) return;
            double x = r.endX(), y = r.endY();
            if (!map.marked(x, y) || s.grid.hazardClearance(x, y) < StrokePlan.REST_CLEARANCE
                    || s.grid.clearance(x, y) < StrokePlan.REST_OBSTACLE_CLEARANCE) return;
            exact.add(new Target(shot, x, y, map.cost(x, y) + 0.5 * hits));
        }

        /**
         * Ends the current run: its middle is a target, scored by the run's length and the putt
         * there; the shot that stops there has the speed² worked out forwards along the path (exact
         * on flat ground, cushions included: each keeps a share of the speed² that does not depend on it).
         */
        void close() {
            if (run.isEmpty()) return;
            double start = run.get(0)[0], end = run.get(run.size() - 1)[0];
            double mid = 0.5 * (start + end);
            double[] m = run.get(0);
            for (double[] p : run) if (Math.abs(p[0] - mid) < Math.abs(m[0] - mid)) m = p;
            run.clear();
            double speed = Math.sqrt(Math.max(m[3], 0));
            if (speed < 0.05 || speed > v0) return;
            double forgiving = Math.min(end - start, LONG_RUN) + 0.05 * map.markedAround(m[1], m[2]);
            double score = map.cost(m[1], m[2]) - 4 * forgiving + 0.5 * m[4];
            double angle = Math.atan2(shot.vy(), shot.vx());
            found.add(new Target(s.sim.limit(Shot.polar(angle, speed)), m[1], m[2], score));
        }
    }
}
