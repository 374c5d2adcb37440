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
 * Learns the friction from where the bot's own strokes came to rest. The model is one scale
 * factor k on the prior ({@link FrictionPrior}): the rest distance falls as k grows, so the k at
 * which the simulated strokes travel as far in total as the observed ones is found by bisection
 * on log k. Exact on a course with one friction (the default only); with zones it fits one
 * average scale (per-zone estimates are not done). Strokes that holed or were lost say little
 * about friction and are not used. Its simulations go through the bot's counting simulator.
 */
public final class FrictionEstimator {
    /** The range of scales searched: μk from 0.002 to 5 with the prior 0.1. */
    static final double MIN_SCALE = 0.02, MAX_SCALE = 50;
    /** Bisection steps on log k: the bracket's 7.8 e-folds shrink below 1e-6 relative. */
    static final int STEPS = 24;

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
     * Adds a stroke and re-fits the scale. Only a stroke that stopped in play is used. Returns
     * whether the estimate changed; a spent budget keeps the old estimate.
     */
    public boolean observe(CountingSimulator sim, Observation o, Outcome outcome) {
        if (outcome != Outcome.STOPPED) return false;
        observations.add(o);
        try {
            double lo = Math.log(MIN_SCALE), hi = Math.log(MAX_SCALE);
            double observed = 0;
            for (Observation ob : observations) observed += Math.hypot(ob.restX() - ob.x(), ob.restY() - ob.y());
            for (int i = 0; i < STEPS; i++) {
                double mid = 0.5 * (lo + hi);
                // Travelling further than observed means the friction guessed is too low.
                if (travelled(sim, Math.exp(mid)) > observed) lo = mid;
                else hi = mid;
            }
            scale = Math.exp(0.5 * (lo + hi));
        } catch (BudgetExhaustedException e) {
            return false;
        }
        world = FrictionPrior.scaled(prior, scale);
        return true;
    }

    private double travelled(CountingSimulator sim, double k) {
        CountingSimulator trial = sim.variant(FrictionPrior.scaled(prior, k), false);
        double total = 0;
        for (Observation o : observations) {
            ShotResult r = trial.simulate(o.x(), o.y(), o.shot());
            total += Math.hypot(r.endX() - o.x(), r.endY() - o.y());
        }
        return total;
    }
}
