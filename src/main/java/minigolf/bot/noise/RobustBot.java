package minigolf.bot.noise;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import minigolf.bot.BotCancelledException;
import minigolf.bot.BotRequest;
import minigolf.bot.Bot;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.CountingSimulator;
import minigolf.bot.CourseMaps;
import minigolf.bot.Shot;
import minigolf.bot.SpeedGuess;
import minigolf.bot.planner.PlannerBot;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * The planner, made aware of the noise ({@link BotRequest#noise()}). The planner's search runs
 * as usual; then its chosen shot and the best other shots it simulated from the ball are scored by
 * their expected strokes over {@link #SAMPLES} draws of the noise model (the same draws for every
 * candidate, so differences come from the shots, not the luck), and a small pattern search in
 * speed and angle moves the winner towards the middle of its success region. A shot replaces the
 * current best only when it is better by a clear margin ({@link #SIGNIFICANCE}), so the planner's
 * strategic choice stands unless the noise model clearly says otherwise. A sure two-putt
 * beats a hole-in-one that succeeds one time in five. Without noise it plays the planner's shot.
 * Budget, time limit and cancel: as every bot (its simulations go through the counting
 * simulator); when the budget runs out it plays the best shot scored so far.
 */
public final class RobustBot implements Bot {
    /** Noise draws per candidate (the same draws for each). */
    static final int SAMPLES = 24;
    /**
     * A candidate replaces the best only if its paired mean difference is this many standard
     * errors below zero: with few draws the luckiest shot would otherwise win (measured: without
     * it the bot drifted from the planner's lay-ups on the mazes and lost strokes).
     */
    static final double SIGNIFICANCE = 2;
    /** Shots the planner simulated that are scored besides its choice. */
    static final int CANDIDATES = 5;
    /** Speeds (as fractions of the planner's ace attempt) of the lay-ups along its line that are scored too. */
    static final double[] LAYUP_FACTORS = {0.7, 0.85};
    /** Pattern-search rounds (each halves the step when no neighbour is better). */
    static final int ROUNDS = 3;

    private final PlannerBot planner = new PlannerBot();
    private final CourseMaps maps = new CourseMaps();

    @Override
    public String name() {
        return "robust";
    }

    @Override
    public Shot nextShot(BotRequest request) {
        Shot base = planner.nextShot(request);
        NoiseModel noise = request.noise();
        if (noise.isNone()) return base;
        Choice choice = null;
        try {
            choice = new Choice(request, base);
            choice.search();
        } catch (BudgetExhaustedException e) {
            // The best scored so far (the planner's shot if none was).
        } catch (BotCancelledException e) {
            throw e;
        } catch (RuntimeException e) {
            request.simulator().recordError(name() + ": " + e);
            if (request.token().isCancelled()) throw new BotCancelledException();
        }
        return choice == null ? base : choice.best;
    }

    /** One stroke's choice: the candidates, the common noise draws and the best so far. */
    private final class Choice {
        final BotRequest request;
        final CountingSimulator sim;
        final World world;
        final double[] startX = new double[SAMPLES], startY = new double[SAMPLES];
        final Shot[] error = new Shot[SAMPLES];
        final StrokeCost cost;
        Shot best;
        /** The best shot's cost on each draw; null before the first candidate. */
        double[] bestCosts;

        Choice(BotRequest request, Shot base) {
            this.request = request;
            this.sim = request.simulator();
            this.world = request.world();
            this.best = base;
            double x = request.ballX(), y = request.ballY();
            SplittableRandom root = new SplittableRandom(request.seed() ^ 0x726F62757374L);
            SplittableRandom positions = root.split(), velocities = root.split();
            for (int k = 0; k < SAMPLES; k++) {
                // A zero shot takes only the error: the start and the velocity offset of draw k.
                PlayedStroke p = ShotNoise.play(request.noise(), world, x, y, Shot.of(0, 0), positions, velocities);
                startX[k] = p.x();
                startY[k] = p.y();
                error[k] = p.shot();
            }
            maps.prepare(world, request.token());
            double hx = world.hole().position().x(), hy = world.hole().position().y();
            cost = new StrokeCost(maps.toHole(), request.noise(), SpeedGuess.maxRoll(world, x, y, hx, hy));
        }

        void search() {
            ShotResult planned = sim.knownResult(best);
            // A lay-up of the planner's is kept as it is: the cost model cannot see the strategy behind it
            // (measured on maze D: moving lay-ups by the model left the ball circling a basin).
            if (planned == null || !CountingSimulator.holed(planned)) return;
            for (Shot c : candidates()) consider(c);
            NoiseModel noise = request.noise();
            double speedStep = Math.max(noise.velocity(), StrokeCost.MIN_SIGMA);
            for (int round = 0; round < ROUNDS; round++) {
                Shot centre = best;
                double speed = Math.hypot(centre.vx(), centre.vy()), angle = Math.atan2(centre.vy(), centre.vx());
                if (speed == 0) return;
                double angleStep = speedStep / speed;
                boolean moved = false;
                for (double[] d : new double[][]{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    Shot n = Shot.polar(angle + d[1] * angleStep, speed + d[0] * speedStep);
                    if (consider(new Shot(n.vx(), n.vy(), centre.vz()))) moved = true;
                }
                if (!moved) speedStep /= 2;
            }
        }

        /**
         * The planner's hole-in-one attempt first, then its other simulated shots from here, best
         * first, spread apart: a safer lay-up may beat a risky ace.
         */
        private List<Shot> candidates() {
            List<Shot> out = new ArrayList<>();
            out.add(best);
            double spread = Math.max(request.noise().velocity(), StrokeCost.MIN_SIGMA) / 2;
            List<Map.Entry<Shot, ShotResult>> known = new ArrayList<>(sim.knownResults().entrySet());
            double x = request.ballX(), y = request.ballY();
            known.sort(Comparator.<Map.Entry<Shot, ShotResult>>comparingDouble(e -> cost.of(e.getValue(), x, y))
                    .thenComparingDouble(e -> e.getKey().vx()).thenComparingDouble(e -> e.getKey().vy()));
            for (Map.Entry<Shot, ShotResult> e : known) {
                if (out.size() > CANDIDATES) break;
                Shot s = e.getKey();
                if (out.stream().noneMatch(o -> Math.hypot(o.vx() - s.vx(), o.vy() - s.vy()) < spread)) out.add(s);
            }
            // The same line, softer: a lay-up short of the hole, for when the ace risks the water or the edge.
            Shot ace = out.get(0);
            for (double f : LAYUP_FACTORS) out.add(new Shot(ace.vx() * f, ace.vy() * f, ace.vz() * f));
            return out;
        }

        /** Scores a shot on every draw; true if it became the best (clearly better: a paired comparison). */
        private boolean consider(Shot shot) {
            Shot intended = sim.limit(shot);
            double[] costs = new double[SAMPLES];
            for (int k = 0; k < SAMPLES; k++) {
                Shot e = error[k];
                Shot played = sim.limit(new Shot(intended.vx() + e.vx(), intended.vy() + e.vy(), intended.vz()));
                costs[k] = cost.of(sim.simulate(startX[k], startY[k], played), request.ballX(), request.ballY());
            }
            if (bestCosts == null || clearlyBetter(costs, bestCosts)) {
                bestCosts = costs;
                best = intended;
                return true;
            }
            return false;
        }
    }

    /** Whether {@code a} costs less than {@code b} by {@link #SIGNIFICANCE} standard errors of the paired mean. */
    static boolean clearlyBetter(double[] a, double[] b) {
        int n = a.length;
        double mean = 0;
        for (int k = 0; k < n; k++) mean += (a[k] - b[k]) / n;
        double var = 0;
        for (int k = 0; k < n; k++) var += (a[k] - b[k] - mean) * (a[k] - b[k] - mean) / (n - 1);
        return mean < -1e-12 && mean + SIGNIFICANCE * Math.sqrt(var / n) < 0;
    }
}
