package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.TrajectoryListener;

/**
 * A serious hole-in-one search on the first stroke, before the planner settles for two (the
 * cheaper {@link HoleInOne} stage failed). Every direction all round, {@link #COARSE_STEP} apart,
 * each shot scored by how near its path passes the hole: walls and boxes bounce shots back, so
 * bank shots (one or several cushions) are among them without modelling the banks. On flat ground
 * the path of a shot does not depend on its speed (friction only shortens it; a wall turns it the
 * same way), so one maximum-speed shot per direction traces every slower one: a slower shot stops
 * somewhere on it. Hills bend slow shots more, so there {@link #HILL_SPEEDS} speeds are swept.
 * Round the nearest passes a finer fan ({@link #FINE_STEP}); from the best of those the speed is
 * cut so the ball would stop where it passed nearest (the energy it still had there spent), and
 * Broyden solves for the hole from that shot.
 *
 * <p>Budget-aware: it runs only when the budget left covers it {@link #BUDGET_FACTOR} times over
 * (the lay-up stages after it need their share) and the shots stay within {@link #cost()}.
 */
final class DenseSweep {
    static final double COARSE_STEP = Math.toRadians(1);
    /** Fractions of the maximum speed swept on hills (one, the maximum, on flat ground). */
    static final double[] HILL_SPEEDS = {1, 0.75, 0.5};
    static final double FINE_STEP = Math.toRadians(0.25);
    /** The fine fan: this many steps either side of a coarse pass; on hills also at ±3% speed. */
    static final int FINE_HALF = 3;
    static final double[] HILL_FINE_SPEEDS = {0.97, 1, 1.03};
    /** A path this near the hole's centre is a pass worth refining. */
    static final double NEAR = 0.3;
    /** Coarse passes refined, and fine passes that start Broyden. */
    static final int PASSES = 8;
    static final int STARTS = 4;
    static final int BUDGET_FACTOR = 3;

    /** A shot and how near its path passed the hole, with the speed it had there. */
    record Pass(Shot shot, double distance, double speedThere) {
    }

    /** A coarse shot that came to rest on the course, and where: a lay-up {@link AceLayup} may look ahead from. */
    record Rest(Shot shot, double x, double y) {
    }

    private final Stroke s;
    /** Lay-up targets collected from the coarse sweep's paths (null: none). */
    private final MapTwoStrokes layups;
    private final double[] speeds;
    private final double[] fineSpeeds;
    /** The coarse sweep's rest points (filled by {@link #holeInOne}). */
    private final List<Rest> rests = new ArrayList<>();

    DenseSweep(Stroke s) {
        this(s, null);
    }

    /** With {@code layups}, the coarse sweep's paths also give {@link MapTwoStrokes} its lay-up targets. */
    DenseSweep(Stroke s, MapTwoStrokes layups) {
        this.s = s;
        this.layups = layups;
        // Push zones and magnets bend slow shots more than fast ones, as hills do.
        boolean flat = Flatness.isFlat(s.world) && s.world.forces() == null;
        this.speeds = flat ? new double[] {1} : HILL_SPEEDS;
        this.fineSpeeds = flat ? new double[] {1} : HILL_FINE_SPEEDS;
    }

    /** Shots the sweep may use at most (Broyden's iterations included, about 16 a start). */
    long cost() {
        long coarse = Math.round(2 * Math.PI / COARSE_STEP) * speeds.length;
        return coarse + (long) PASSES * (2 * FINE_HALF + 1) * fineSpeeds.length + STARTS * 17L;
    }

    /** Whether the budget left leaves room for the sweep and the stages after it. */
    boolean affordable() {
        return s.sim.remaining() >= BUDGET_FACTOR * cost();
    }

    /** A shot that holes out, or null. */
    Shot holeInOne() {
        if (!affordable()) return null;
        s.sim.phase("dense sweep");
        double vMax = s.sim.maxSpeed();
        int directions = (int) Math.round(2 * Math.PI / COARSE_STEP);
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        List<Trial> coarse = new ArrayList<>();
        for (int i = 0; i < directions; i++) {
            double angle = holeAngle + i * COARSE_STEP;
            for (double fraction : speeds) {
                Shot shot = s.sim.limit(Shot.polar(angle, vMax * fraction));
                coarse.add(trial(shot, layups == null ? null : layups.tracer(shot), null));
            }
        }
        List<Pass> near = new ArrayList<>();
        Trial holed = sweep(coarse, true, p -> {
            if (p.distance() < NEAR) near.add(p);
        });
        if (holed != null) return holed.shot();
        if (layups != null) layups.swept();
        near.sort((a, b) -> Double.compare(a.distance(), b.distance()));
        s.sim.phase("dense fine");
        List<Trial> fan = new ArrayList<>();
        List<Pass> refined = new ArrayList<>();
        for (Pass c : near) {
            if (refined.size() >= PASSES) break;
            // One fan per pass: a neighbour of a refined pass (within the fan) is the same line.
            if (refined.stream().anyMatch(r -> sameLine(r.shot(), c.shot()))) continue;
            refined.add(c);
            Pass centre = null;
            for (int k = -FINE_HALF; k <= FINE_HALF; k++) {
                for (double f : fineSpeeds) {
                    if (k == 0 && f == 1) {
                        // Already simulated: it joins the fine passes just before the fan's next shot.
                        centre = c;
                        continue;
                    }
                    Shot shot = s.sim.limit(Shot.polar(angle(c.shot()) + k * FINE_STEP, c.shot().speed() * f));
                    fan.add(trial(shot, null, centre));
                    centre = null;
                }
            }
        }
        List<Pass> fine = new ArrayList<>();
        holed = sweep(fan, false, fine::add);
        if (holed != null) return holed.shot();
        fine.sort((a, b) -> Double.compare(a.distance(), b.distance()));
        s.sim.phase("dense refine");
        int starts = 0;
        for (Pass p : fine) {
            if (starts >= STARTS) break;
            Shot slowed = stopWhereNearest(p);
            Eval e = s.evaluate(slowed, s.holeX, s.holeY);
            if (e.holed()) return slowed;
            // Hills bend a slowed shot off its fast line: Broyden from as far as the planner's own sweep does.
            if (e.penalty() || Math.hypot(e.restX() - s.holeX, e.restY() - s.holeY) > Math.max(1, 0.25 * s.pathLength)) continue;
            starts++;
            Attempt a = s.solveHole(slowed, e);
            if (a.holed()) return a.shot();
        }
        return null;
    }

    /** The coarse sweep's shots that came to rest (in sweep order; empty before {@link #holeInOne}). */
    List<Rest> rests() {
        return rests;
    }

    /**
     * One shot of a sweep: where its path passes the hole, the lay-ups on it (null: none), and a
     * fan's centre (null: none), a pass already simulated that is listed just before this shot's.
     */
    private record Trial(Shot shot, Approach approach, MapTwoStrokes.Runs runs, Pass centreBefore) {
    }

    private Trial trial(Shot shot, MapTwoStrokes.Runs runs, Pass centreBefore) {
        return new Trial(shot, new Approach(s.holeX, s.holeY, s.px, s.py, shot), runs, centreBefore);
    }

    /**
     * Simulates the trials in order, each pass (and a fan's centre before it) to {@code passes}; the
     * trial that holes out (which ends the sweep), or null. With {@code keepRest} the rest points are kept.
     */
    private Trial sweep(List<Trial> trials, boolean keepRest, java.util.function.Consumer<Pass> passes) {
        return s.sim.simulateInOrder(s.px, s.py, trials, new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Trial t) {
                return t.shot();
            }

            @Override
            public TrajectoryListener listener(Trial t) {
                return t.runs() == null ? t.approach() : Stroke.both(t.approach(), t.runs());
            }

            @Override
            public boolean stopsAt(Trial t, ShotResult r) {
                if (t.runs() != null) t.runs().end(r);
                if (CountingSimulator.holed(r)) return true;
                if (keepRest && r.outcome() == Outcome.STOPPED) rests.add(new Rest(t.shot(), r.endX(), r.endY()));
                if (t.centreBefore() != null) passes.accept(t.centreBefore());
                Approach a = t.approach();
                passes.accept(new Pass(t.shot(), Math.sqrt(a.best), Math.hypot(a.cvx, a.cvy)));
                return false;
            }
        });
    }

    /** The shot slowed so the ball has no speed left where it passed nearest: v0² - v² (work on the way kept). */
    static Shot stopWhereNearest(Pass p) {
        double v0 = p.shot().speed(), v = Math.min(p.speedThere(), 0.98 * v0);
        return Shot.polar(angle(p.shot()), Math.sqrt(v0 * v0 - v * v));
    }

    private static double angle(Shot shot) {
        return Math.atan2(shot.vy(), shot.vx());
    }

    private static boolean sameLine(Shot a, Shot b) {
        return Math.abs(Math.IEEEremainder(angle(a) - angle(b), 2 * Math.PI)) <= FINE_HALF * FINE_STEP + 1e-9
                && Math.abs(a.speed() - b.speed()) < 0.1 * b.speed();
    }
}
