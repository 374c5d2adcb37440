package minigolf.bot.friction;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * Learns the friction from where the bot's own strokes ended. The model is one scale factor k on
 * the prior ({@link FrictionPrior}); the estimate is the k whose simulated strokes end nearest the
 * observed ends (least squares over every stroke so far). Where balls bounce off walls that
 * misfit has several valleys (a rest distance that only falls with k would not: a wall can stop a
 * fast ball short), so the k are first scanned on a log grid, with the current estimate among
 * them, and the best refined by golden-section search. Exact on a course with one friction; with
 * zones it fits one average scale (per-zone estimates are not done). Its simulations go through
 * the bot's counting simulator.
 */
public final class FrictionEstimator {
    /** The range of scales searched: μk from 0.002 to 5 with the prior 0.1. */
    static final double MIN_SCALE = 0.02, MAX_SCALE = 50;
    /** Scan points over log k (a ratio of 1.39 between neighbours). */
    static final int SCAN = 25;
    /** Golden-section steps: the bracket of two scan steps shrinks to 2e-5 of log k. */
    static final int GOLDEN = 24;
    /** Relative changes of the scale below this keep the current estimate (and the bot's world). */
    static final double CHANGE = 1e-3;

    /** A stroke the bot played: its start, its shot and where the ball came to rest. */
    public record Observation(double x, double y, Shot shot, double restX, double restY) {
    }

    /** The prior world (scale 1): what the bot may see. */
    private final World prior;
    private final List<Observation> observations = new ArrayList<>();
    private double scale = 1;
    private World world;

    /** @param prior the world the bot may see ({@link FrictionPrior#scaled} at scale 1) */
    public FrictionEstimator(World prior) {
        this.prior = prior;
        this.world = prior;
    }

    /** The world with the current estimate (the prior before any observation). */
    public World world() {
        return world;
    }

    public double scale() {
        return scale;
    }

    public double kineticFriction() {
        return FrictionPrior.KINETIC * scale;
    }

    public double staticFriction() {
        return FrictionPrior.STATIC * scale;
    }

    /**
     * Adds a stroke and re-fits the scale. A holed stroke (or one stopped by the time limit) is not
     * used; a lost one is, with where it entered the water or left the course as its end (a ball
     * that keeps going into the water on a fast green is exactly the one that must learn). Returns
     * whether the estimate changed by more than {@link #CHANGE}; a spent budget keeps the old one.
     */
    public boolean observe(CountingSimulator sim, Observation o, Outcome outcome) {
        if (outcome == Outcome.HOLED || outcome == Outcome.TIMEOUT) return false;
        observations.add(o);
        double old = scale;
        try {
            scale = fit(sim, old);
        } catch (BudgetExhaustedException e) {
            scale = old;
            return false;
        }
        // A bot keeps its maps and caches while the world object stays: only a real change makes a new one.
        if (Math.abs(Math.log(scale / old)) <= CHANGE) {
            scale = old;
            return false;
        }
        world = FrictionPrior.scaled(prior, scale);
        return true;
    }

    /** The scan, then golden-section refinement between the best grid point's neighbours (log k). */
    private double fit(CountingSimulator sim, double current) {
        double lo = Math.log(MIN_SCALE), hi = Math.log(MAX_SCALE), step = (hi - lo) / (SCAN - 1);
        double bestLog = Math.log(current), best = misfit(sim, current);
        if (best == 0) return current;
        for (int i = 0; i < SCAN; i++) {
            double m = misfit(sim, Math.exp(lo + i * step));
            if (m < best) {
                best = m;
                bestLog = lo + i * step;
            }
        }
        double a = Math.max(lo, bestLog - step), b = Math.min(hi, bestLog + step);
        double g = (Math.sqrt(5) - 1) / 2;
        double c = b - g * (b - a), d = a + g * (b - a);
        double mc = misfit(sim, Math.exp(c)), md = misfit(sim, Math.exp(d));
        for (int i = 0; i < GOLDEN; i++) {
            if (mc <= md) {
                b = d;
                d = c;
                md = mc;
                c = b - g * (b - a);
                mc = misfit(sim, Math.exp(c));
            } else {
                a = c;
                c = d;
                mc = md;
                d = a + g * (b - a);
                md = misfit(sim, Math.exp(d));
            }
        }
        double refined = mc <= md ? c : d;
        return Math.min(mc, md) <= best ? Math.exp(refined) : Math.exp(bestLog);
    }

    /** Sum of squared distances between simulated and observed ends at scale k. */
    private double misfit(CountingSimulator sim, double k) {
        CountingSimulator trial = sim.variant(FrictionPrior.scaled(prior, k), false);
        double total = 0;
        for (Observation o : observations) {
            ShotResult r = trial.simulate(o.x(), o.y(), o.shot());
            double dx = r.endX() - o.restX(), dy = r.endY() - o.restY();
            total += dx * dx + dy * dy;
        }
        return total;
    }
}
