package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Shot;

/**
 * The planner's last stage, when no one- or two-stroke game is found: the stroke plan's lay-up,
 * a sweep all round when that leaves many strokes (with a look-ahead one stroke further far from
 * the hole), a point along the shortest path, and last a progress sweep.
 */
final class Layup {
    /** The plan sweep's speeds, fractions of the maximum (its directions: LAYUP_STEP apart). */
    static final double[] PLAN_SWEEP_SPEEDS = {0.3, 0.5, 0.7, 0.9};
    /** The plan sweep replaces the plan's lay-up when that leaves this many strokes or more. */
    static final int SWEEP_STROKES_LEFT = 3;
    /** A plan-sweep shot resting this close to the hole (distance field) starts Broyden. */
    static final double SWEEP_REFINE = 0.6;
    /**
     * Far from the hole (the plan's lay-up leaves BEAM_LEFT strokes or more) the plan sweep looks
     * one stroke further from its best BEAM rest points, at least BEAM_SPACING apart. Measured on
     * the mazes: maze-a 6 -> 5 strokes; applied closer it cost simulations and gained nothing.
     */
    static final int BEAM = 3;
    static final int BEAM_LEFT = 5;
    static final double BEAM_SPACING = 1.0;

    private final Stroke s;

    Layup(Stroke s) {
        this.s = s;
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
        if (s.path.isEmpty()) return progressSweep();
        int strokesLeft = Math.max(2, (int) Math.ceil(s.pathLength / (0.99 * reach)));
        double along = Math.min(s.pathLength / strokesLeft, 0.99 * reach);
        for (int attempt = 0; attempt < 4; attempt++) {
            double[] w = s.visiblePointAlongPath(along);
            double distance = Math.hypot(w[0] - s.px, w[1] - s.py);
            Shot start = s.guessTo(Math.atan2(w[1] - s.py, w[0] - s.px), distance, w[0], w[1]);
            Attempt a = s.broydenTo(start, null, w[0], w[1], 10, Math.max(0.1, 0.05 * distance), false);
            if (a.converged()) return a.shot();
            along *= 0.7;
        }
        return progressSweep();
    }

    /**
     * The lay-up the stroke plan suggests: of the cells a straight putt from the ball reaches,
     * those with the fewest strokes left, nearest the hole and clearest of water first.
     */
    Planned plannedLayup() {
        s.sim.phase("plan");
        StrokePlan p = s.plan.get();
        List<int[]> options = new ArrayList<>();
        int fewest = Integer.MAX_VALUE;
        for (int i = 0; i < p.cells(); i++) {
            int left = p.strokes(i);
            if (left == Integer.MAX_VALUE || left > fewest) continue;
            if (!p.putt(s.px, s.py, p.x(i), p.y(i))) continue;
            if (left < fewest) {
                fewest = left;
                options.clear();
            }
            options.add(new int[] {i});
        }
        if (options.isEmpty()) return null;
        options.sort((a, b) -> Double.compare(layupCost(p, a[0]), layupCost(p, b[0])));
        s.sim.phase("lay-up (" + fewest + " to go)");
        Shot firstConverged = null;
        for (int k = 0; k < Math.min(fewest == 1 ? 6 : 4, options.size()); k++) {
            int i = options.get(k)[0];
            double tx = p.x(i), ty = p.y(i);
            double distance = Math.hypot(tx - s.px, ty - s.py);
            Shot start = s.guessTo(Math.atan2(ty - s.py, tx - s.px), distance, tx, ty);
            Attempt a = s.broydenTo(start, null, tx, ty, 10, 0.5 * StrokePlan.REST_CLEARANCE, false);
            if (!a.converged()) continue;
            if (fewest > 1) return new Planned(a.shot(), false, fewest);
            // Look ahead: keep the lay-up from which the next stroke really holes out
            // (the straight-putt plan does not know how the hills bend the ball).
            if (firstConverged == null) firstConverged = a.shot();
            s.triedLayups.add(new double[] {a.last().restX(), a.last().restY()});
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, a.last().restX(), a.last().restY(), s.plan);
            if (next.solvedHole()) {
                return new Planned(a.shot(), true, fewest);
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
        if (planLeft < BEAM_LEFT) return ranked.get(0).shot();
        // Look one stroke further: from the best few rest points (at least BEAM_SPACING apart)
        // a sweep of their own; play the one whose best follow-up rests nearest the hole.
        s.sim.phase("plan look-ahead");
        List<Eval> tried = new ArrayList<>();
        Eval best = ranked.get(0);
        double bestNext = Double.POSITIVE_INFINITY;
        for (Eval e : ranked) {
            if (tried.size() == BEAM) break;
            boolean near = false;
            for (Eval t : tried) near |= Math.hypot(t.restX() - e.restX(), t.restY() - e.restY()) < BEAM_SPACING;
            if (near) continue;
            tried.add(e);
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, e.restX(), e.restY(), s.plan);
            Layup nextLayup = new Layup(next);
            if (nextLayup.sweepAllRound() != null) return e.shot();
            List<Eval> after = nextLayup.safeRests();
            double d = after.isEmpty() ? Double.POSITIVE_INFINITY : s.field.at(after.get(0).restX(), after.get(0).restY());
            if (d < bestNext) {
                bestNext = d;
                best = e;
            }
        }
        return best.shot();
    }

    /** The resting probes of this stroke well clear of water and a little of obstacles, nearest the hole first. */
    List<Eval> safeRests() {
        List<Eval> safe = new ArrayList<>();
        for (Eval e : s.restingProbes) {
            if (s.grid.hazardClearance(e.restX(), e.restY()) < StrokePlan.REST_CLEARANCE
                    || s.grid.clearance(e.restX(), e.restY()) < StrokePlan.REST_OBSTACLE_CLEARANCE
                    || !Double.isFinite(s.field.at(e.restX(), e.restY()))) continue;
            safe.add(e);
        }
        safe.sort((a, b) -> Double.compare(s.field.at(a.restX(), a.restY()), s.field.at(b.restX(), b.restY())));
        return safe;
    }

    /** Directions LAYUP_STEP apart all round at the plan sweep's speeds; a shot that holes, or null. */
    Shot sweepAllRound() {
        s.sim.phase("plan sweep");
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        for (int k = 0; k * Stroke.LAYUP_STEP < 2 * Math.PI - 1e-9; k++) {
            for (double fraction : PLAN_SWEEP_SPEEDS) {
                Shot shot = s.sim.limit(Shot.polar(holeAngle + k * Stroke.LAYUP_STEP, fraction * s.sim.maxSpeed()));
                Eval e = s.evaluate(shot, s.holeX, s.holeY);
                if (e.holed()) return shot;
                // A shot (banked, curved) resting near the hole: Broyden may hole it.
                if (!e.penalty() && s.field.at(e.restX(), e.restY()) < SWEEP_REFINE) {
                    Attempt a = s.solveHole(shot, e);
                    if (a.holed()) return a.shot();
                }
            }
        }
        return null;
    }

    double layupCost(StrokePlan p, int i) {
        double d = s.field.at(p.x(i), p.y(i));
        return (Double.isFinite(d) ? d : 1e6) - Math.min(s.grid.hazardClearance(p.x(i), p.y(i)), 1.0)
                - 0.3 * Math.min(s.grid.clearance(p.x(i), p.y(i)), 0.5);
    }

    /** The last resort: many directions and speeds, keep the rest point nearest the hole. */
    Shot progressSweep() {
        s.sim.phase("progress");
        double reach = Math.max(0.5, s.maxRoll());
        for (double angle : s.sweepAngles()) {
            for (double fraction : new double[] {0.35, 0.7, 1.0}) {
                s.evaluate(s.guessLength(angle, fraction * Math.min(reach, s.pathLength + 1)), s.holeX, s.holeY);
            }
        }
        return s.sim.bestShot();
    }
}
