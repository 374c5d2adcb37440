package minigolf.bot.friction;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.DoubleUnaryOperator;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * Learns the friction from where the bot's own strokes ended. The model is a scale factor on the
 * prior ({@link FrictionPrior}) for each friction region the bot can see: the course's default and
 * each zone (a player sees where the sand is, not how slow it is). The estimate is the set of scales
 * whose simulated strokes end nearest the observed ends (least squares over every stroke so far).
 *
 * <p>First one common scale k is fitted: where balls bounce off walls that misfit has several
 * valleys (a wall can stop a fast ball short), so k is scanned on a log grid, with the current
 * estimate among the points, and the best refined by golden-section search. That is exact on a
 * course with one friction. On a course with zones, unless k already ends every stroke within
 * {@value #FITS} m of where it ended, the regions' scales are then refined together from k
 * ({@link RegionFit}, Levenberg-Marquardt: one stroke often crosses two regions, so they must move
 * together); a region no stroke has crossed keeps k. The separate
 * scales are kept only when they fit the strokes clearly better than k alone (misfit below
 * {@value #SEPARATE} of k's): with noisy strokes a region must earn its own value. Its simulations
 * go through the bot's counting simulator.
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
    /** The share of the common fit's misfit below which separate region scales are believed. */
    static final double SEPARATE = 0.5;
    /** A common fit whose ends are all this close (m, root mean square) already explains the strokes. */
    static final double FITS = 1e-3;

    /** A stroke the bot played: its start, its shot and where the ball came to rest. */
    public record Observation(double x, double y, Shot shot, double restX, double restY) {
    }

    /** The prior world (scale 1): what the bot may see. */
    private final World prior;
    private final List<Observation> observations = new ArrayList<>();
    private double[] scales;
    private World world;

    /** @param prior the world the bot may see ({@link FrictionPrior#scaled} at scale 1) */
    public FrictionEstimator(World prior) {
        this.prior = prior;
        this.world = prior;
        this.scales = new double[FrictionPrior.regions(prior)];
        Arrays.fill(scales, 1);
    }

    /** The world with the current estimate (the prior before any observation). */
    public World world() {
        return world;
    }

    /** The scale of the course's default friction. */
    public double scale() {
        return scales[0];
    }

    /** The scales of every region: the default, then each zone in order. */
    public double[] regionScales() {
        return scales.clone();
    }

    public double kineticFriction() {
        return FrictionPrior.KINETIC * scales[0];
    }

    public double staticFriction() {
        return FrictionPrior.STATIC * scales[0];
    }

    /**
     * Adds a stroke and re-fits the scales. A holed stroke (or one stopped by the time limit) is not
     * used; a lost one is, with where it entered the water or left the course as its end (a ball
     * that keeps going into the water on a fast green is exactly the one that must learn). Returns
     * whether the estimate changed by more than {@link #CHANGE}; a spent budget keeps the old one.
     */
    public boolean observe(CountingSimulator sim, Observation o, Outcome outcome) {
        if (outcome == Outcome.HOLED || outcome == Outcome.TIMEOUT) return false;
        observations.add(o);
        double[] fitted;
        try {
            fitted = fit(sim);
        } catch (BudgetExhaustedException e) {
            return false;
        }
        // A bot keeps its maps and caches while the world object stays: only a real change makes a new one.
        double change = 0;
        for (int r = 0; r < scales.length; r++) change = Math.max(change, Math.abs(Math.log(fitted[r] / scales[r])));
        if (change <= CHANGE) return false;
        scales = fitted;
        world = FrictionPrior.scaled(prior, scales);
        return true;
    }

    private double[] fit(CountingSimulator sim) {
        double current = scales[0];
        double[] common = new double[scales.length];
        double k = minimize(c -> misfit(sim, uniform(c)), Math.log(MIN_SCALE), Math.log(MAX_SCALE), SCAN, GOLDEN,
                Math.log(current));
        Arrays.fill(common, k);
        if (scales.length == 1) return common;
        double commonMisfit = misfit(sim, common);
        if (commonMisfit <= observations.size() * FITS * FITS) return common;
        double[] separate = RegionFit.refine(s -> residuals(sim, s), common, Math.log(MIN_SCALE), Math.log(MAX_SCALE));
        return misfit(sim, separate) < SEPARATE * commonMisfit ? separate : common;
    }

    private double[] uniform(double logScale) {
        double[] s = new double[scales.length];
        Arrays.fill(s, Math.exp(logScale));
        return s;
    }

    /**
     * The scale (not its log) minimising f over log scales in [lo, hi]: a scan of n points with the
     * current value among them, then golden-section refinement between the best point's neighbours.
     */
    private static double minimize(DoubleUnaryOperator f, double lo, double hi, int n, int golden, double current) {
        double step = (hi - lo) / (n - 1);
        double bestLog = current, best = f.applyAsDouble(current);
        if (best == 0) return Math.exp(current);
        for (int i = 0; i < n; i++) {
            double m = f.applyAsDouble(lo + i * step);
            if (m < best) {
                best = m;
                bestLog = lo + i * step;
            }
        }
        double a = Math.max(lo, bestLog - step), b = Math.min(hi, bestLog + step);
        double g = (Math.sqrt(5) - 1) / 2;
        double c = b - g * (b - a), d = a + g * (b - a);
        double mc = f.applyAsDouble(c), md = f.applyAsDouble(d);
        for (int i = 0; i < golden; i++) {
            if (mc <= md) {
                b = d;
                d = c;
                md = mc;
                c = b - g * (b - a);
                mc = f.applyAsDouble(c);
            } else {
                a = c;
                c = d;
                mc = md;
                d = a + g * (b - a);
                md = f.applyAsDouble(d);
            }
        }
        double refined = mc <= md ? c : d;
        return Math.min(mc, md) <= best ? Math.exp(refined) : Math.exp(bestLog);
    }

    /** Sum of squared distances between simulated and observed ends with these region scales. */
    private double misfit(CountingSimulator sim, double[] s) {
        double total = 0;
        for (double r : residuals(sim, s)) total += r * r;
        return total;
    }

    /** Simulated minus observed end, x and y of each stroke in turn, with these region scales. */
    private double[] residuals(CountingSimulator sim, double[] s) {
        CountingSimulator trial = sim.variant(FrictionPrior.scaled(prior, s), false);
        double[] res = new double[2 * observations.size()];
        for (int i = 0; i < observations.size(); i++) {
            Observation o = observations.get(i);
            ShotResult r = trial.simulate(o.x(), o.y(), o.shot());
            res[2 * i] = r.endX() - o.restX();
            res[2 * i + 1] = r.endY() - o.restY();
        }
        return res;
    }
}
