package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Shot;

/**
 * The planner's second stage: two strokes. Lay-ups from the rest points this stroke's probes
 * already found, then a lay-up sweep all round; a lay-up counts when the look-ahead (does one putt
 * hole from its rest point?) says so.
 */
final class TwoStrokes {
    /** Lay-ups tried from the hole-in-one search's resting probes, at least this far apart. */
    static final int TWO_STROKE_TRIES = 3;
    static final double TWO_STROKE_SPACING = 0.4;
    /** The lay-up sweep's rolls, fractions of the reach; the look-ahead runs from its best LAYUP_TRIES rest points. */
    static final double[] LAYUP_LENGTHS = {0.5, 0.8};
    static final int LAYUP_TRIES = 6;

    private final Stroke s;

    TwoStrokes(Stroke s) {
        this.s = s;
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
        return tryLayups(s.triedLayups, TWO_STROKE_TRIES, false);
    }

    /** The second half of {@link #twoStrokes}: the lay-up sweep, then the look-ahead from its best rest points. */
    Shot layupSweep() {
        s.sim.phase("lay-up sweep");
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        double longest = Math.min(0.99 * s.maxRoll(), 1.1 * s.pathLength);
        for (int k = 0; k * Stroke.LAYUP_STEP <= Math.PI + 1e-9; k++) {
            for (int sign : new int[] {1, -1}) {
                if ((k == 0 || k * Stroke.LAYUP_STEP >= Math.PI - 1e-9) && sign < 0) continue;
                double angle = holeAngle + sign * k * Stroke.LAYUP_STEP;
                for (double fraction : LAYUP_LENGTHS) {
                    Shot shot = s.guessLength(angle, fraction * longest);
                    if (s.evaluate(shot, s.holeX, s.holeY).holed()) return shot;
                }
            }
        }
        s.sim.phase("two strokes");
        return tryLayups(s.triedLayups, LAYUP_TRIES, true);
    }

    /** The wide lay-up sweep ({@code planner-aces}): directions this far apart, at these fractions of the maximum speed. */
    static final double WIDE_STEP = Math.toRadians(5);
    static final double[] WIDE_SPEEDS = {0.4, 0.6, 0.8, 1.0};
    static final int WIDE_TRIES = 10;

    /**
     * Where the plan's lay-up leaves more than one putt (a maze), the lay-up sweep's two roll
     * lengths near the hole's line miss the lay-ups that one far-rolling or banked shot reaches:
     * every direction {@link #WIDE_STEP} apart at {@link #WIDE_SPEEDS}, then the look-ahead
     * from the best {@link #WIDE_TRIES} rest points from which a straight putt sees the hole.
     */
    Shot wideLayupSweep() {
        s.sim.phase("wide lay-up sweep");
        int directions = (int) Math.round(2 * Math.PI / WIDE_STEP);
        double holeAngle = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        for (int i = 0; i < directions; i++) {
            for (double f : WIDE_SPEEDS) {
                Shot shot = s.sim.limit(Shot.polar(holeAngle + i * WIDE_STEP, f * s.sim.maxSpeed()));
                if (s.evaluate(shot, s.holeX, s.holeY).holed()) return shot;
            }
        }
        s.sim.phase("two strokes");
        Shot shot = tryLayups(s.triedLayups, WIDE_TRIES, false);
        if (shot != null) return shot;
        return bankedLayup();
    }

    /** Lay-ups already tried (nearest first) once more, the look-ahead now allowing a bank shot off a wall. */
    private Shot bankedLayup() {
        int attempts = 0;
        for (double[] t : s.triedLayups) {
            if (attempts++ == WIDE_TRIES) break;
            for (Eval e : s.restingProbes) {
                if (e.restX() != t[0] || e.restY() != t[1]) continue;
                Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, e.restX(), e.restY(), s.plan);
                Shot bank = new HoleInOne(next).bankShot();
                if (bank != null) {
                    s.solved.add(new Solved(s.world, e.restX(), e.restY(), bank));
                    return e.shot();
                }
                break;
            }
        }
        return null;
    }

    /**
     * Look-ahead from up to {@code tries} resting probes not near one already tried: those
     * from which a straight putt sees the hole clear of water within reach first (the cheap
     * "can I hole from here" test), each group nearest the hole on the distance field first.
     */
    Shot tryLayups(List<double[]> tried, int tries, boolean puttOnly) {
        StrokePlan p = s.plan.get();
        List<double[]> options = new ArrayList<>();
        for (int i = 0; i < s.restingProbes.size(); i++) {
            Eval e = s.restingProbes.get(i);
            double d = s.field.at(e.restX(), e.restY());
            if (s.grid.hazardClearance(e.restX(), e.restY()) < StrokePlan.REST_CLEARANCE
                    || s.grid.clearance(e.restX(), e.restY()) < StrokePlan.REST_OBSTACLE_CLEARANCE
                    || !Double.isFinite(d)) continue;
            boolean putt = p.putt(e.restX(), e.restY(), s.holeX, s.holeY);
            if (puttOnly && !putt) continue;
            double rank = putt ? d : 1e4 + d;
            options.add(new double[] {rank, i});
        }
        options.sort((a, b) -> Double.compare(a[0], b[0]));
        int attempts = 0;
        for (double[] o : options) {
            if (attempts == tries) break;
            Eval e = s.restingProbes.get((int) o[1]);
            boolean near = false;
            for (double[] t : tried) near |= Math.hypot(t[0] - e.restX(), t[1] - e.restY()) < TWO_STROKE_SPACING;
            if (near) continue;
            tried.add(new double[] {e.restX(), e.restY()});
            attempts++;
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, e.restX(), e.restY(), s.plan);
            if (next.solvedHole()) return e.shot();
        }
        return null;
    }
}
