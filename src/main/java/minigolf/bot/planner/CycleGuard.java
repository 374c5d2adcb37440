package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * The planner's memory of the positions it has played from in one game, and the rule that keeps
 * it out of cycles: no stroke may lead back. A stroke leads back when the ball is lost (it goes
 * back where it was), runs out of simulated time, or comes to rest within {@link #RADIUS} of a
 * position already played from, the ball's own included (no progress). Such a choice is replaced
 * by the best known shot from the ball that does not lead back; only when no shot known does, the
 * original choice stands.
 */
final class CycleGuard {
    /** A rest point this close to a position played from counts as that position. */
    static final double RADIUS = 0.1;

    private final List<double[]> visited = new ArrayList<>();
    private World world;

    /**
     * Records the ball's position; a new course or a game's first stroke starts a fresh memory. A
     * world with the same terrain (the same course with re-estimated friction, FrictionPrior) keeps it.
     */
    void visit(World w, double x, double y, int strokesTaken) {
        if (world == null || w.terrain() != world.terrain() || strokesTaken == 0) {
            visited.clear();
            world = w;
        }
        if (!near(x, y)) visited.add(new double[] {x, y});
    }

    /** Positions played from so far (read-only copies). */
    List<double[]> visited() {
        List<double[]> copy = new ArrayList<>();
        for (double[] v : visited) copy.add(v.clone());
        return copy;
    }

    boolean leadsBack(ShotResult r) {
        if (r.outcome() == Outcome.HOLED) return false;
        if (r.outcome() != Outcome.STOPPED) return true;
        return near(r.endX(), r.endY());
    }

    private boolean near(double x, double y) {
        for (double[] v : visited) {
            if (Math.hypot(v[0] - x, v[1] - y) < RADIUS) return true;
        }
        return false;
    }

    /**
     * {@code chosen} when it does not lead back; else the best-scored known shot that does not
     * (lowest {@code score}); null when no known shot makes progress.
     */
    Shot choose(Shot chosen, ShotResult chosenResult, Map<Shot, ShotResult> known, CountingSimulator.ShotScore score) {
        if (!leadsBack(chosenResult)) return chosen;
        Shot best = null;
        double bestScore = Double.POSITIVE_INFINITY;
        for (Map.Entry<Shot, ShotResult> e : known.entrySet()) {
            if (leadsBack(e.getValue())) continue;
            double s = score.score(e.getValue());
            // Ties go to the slower shot, then the smaller vx, vy: the same choice whatever the map's order.
            if (s < bestScore || (s == bestScore && best != null && compare(e.getKey(), best) < 0)) {
                bestScore = s;
                best = e.getKey();
            }
        }
        return best;
    }

    private static int compare(Shot a, Shot b) {
        int c = Double.compare(a.speed(), b.speed());
        if (c != 0) return c;
        c = Double.compare(a.vx(), b.vx());
        return c != 0 ? c : Double.compare(a.vy(), b.vy());
    }
}
