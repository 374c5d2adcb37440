package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Shot;

/**
 * Two strokes as the best players of the classic tracks play them: a lay-up to a spot from which
 * a shot all round aces (cushions, pushes, teleports), where the straight look-ahead of
 * {@link TwoStrokes} sees no one-putt. Of the rest points of this stroke's {@link DenseSweep}, up
 * to {@link #TRIES} nearest the hole on the distance field (clear of water and walls, at least
 * {@link #SPACING} apart and from the ball) each get the straight look-ahead, then a dense sweep
 * of their own; the first that holes out is kept for the next stroke ({@link Solved}).
 *
 * <p>A look-ahead sweep costs what the stroke's own sweep costs (about 500 simulations on flat
 * ground, 1,300 with pushes): a game spends at most {@link #SHARE} of its budget on them, and
 * only out of its first half ({@link #allowance}), so the later strokes keep their own sweeps. With
 * the share alone, games that spent the whole 20,000 rose from 16 to 26 of the 177 sample tracks.
 */
final class AceLayup {
    static final int TRIES = 3;
    static final double SPACING = 0.5;
    static final double SHARE = 0.25;

    private final Stroke s;
    /** What this game's look-aheads may still spend. */
    private final long allowance;
    private long spent;

    /**
     * What the look-aheads may spend now: the rest of the game's share, but never so much that
     * less than half the budget would be left (0 once half is spent).
     */
    static long allowance(long budget, long remaining, long spentSoFar) {
        long share = (long) (SHARE * budget) - spentSoFar;
        long aboveHalf = remaining - budget / 2;
        return Math.max(0, Math.min(share, aboveHalf));
    }

    AceLayup(Stroke s, long allowance) {
        this.s = s;
        this.allowance = allowance;
    }

    /** The simulations this search used. */
    long spent() {
        return spent;
    }

    /** A lay-up among {@code rests} from which the next stroke holes out, or null. */
    Shot search(List<DenseSweep.Rest> rests) {
        long before = s.sim.count();
        try {
            return choose(rests);
        } finally {
            spent = s.sim.count() - before;
        }
    }

    private Shot choose(List<DenseSweep.Rest> rests) {
        List<DenseSweep.Rest> options = new ArrayList<>();
        for (DenseSweep.Rest r : rests) {
            if (Math.hypot(r.x() - s.px, r.y() - s.py) < SPACING || !Double.isFinite(s.field.at(r.x(), r.y()))
                    || s.grid.hazardClearance(r.x(), r.y()) < StrokePlan.REST_CLEARANCE
                    || s.grid.clearance(r.x(), r.y()) < StrokePlan.REST_OBSTACLE_CLEARANCE) continue;
            options.add(r);
        }
        options.sort((a, b) -> Double.compare(s.field.at(a.x(), a.y()), s.field.at(b.x(), b.y())));
        List<DenseSweep.Rest> tried = new ArrayList<>();
        long start = s.sim.count();
        for (DenseSweep.Rest r : options) {
            if (tried.size() == TRIES) break;
            if (tried.stream().anyMatch(t -> Math.hypot(t.x() - r.x(), t.y() - r.y()) < SPACING)) continue;
            tried.add(r);
            s.sim.phase("ace lay-up");
            Stroke next = new Stroke(s.solved, s.sim, s.probe, s.maps, r.x(), r.y(), s.plan);
            // The straight look-ahead first (a few dozen simulations; it records its own solution).
            if (next.solvedHole()) return r.shot();
            DenseSweep sweep = new DenseSweep(next);
            if (s.sim.count() - start + sweep.cost() > allowance) break;
            Shot ace = sweep.holeInOne();
            if (ace != null) {
                s.solved.add(new Solved(s.world, r.x(), r.y(), ace));
                return r.shot();
            }
        }
        return null;
    }
}
