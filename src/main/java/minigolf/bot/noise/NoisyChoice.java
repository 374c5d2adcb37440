package minigolf.bot.noise;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * One stroke's choice under noise, for {@link RobustBot}: the planner's shot, the best other shots
 * the planner simulated from the ball (by their noiseless end on the {@link ValueMap}), softer
 * shots along a hole-in-one attempt's line, and a pattern search in speed and angle round the best,
 * each played on the same {@link #SAMPLES} draws of the noise (so differences come from the shots,
 * not the luck) and scored by expected strokes: 1 for a holed draw, 1 + V(end) for a ball at rest,
 * and for a lost ball the penalty and the stroke again from where the ball lay.
 *
 * <p>The value of the ball's own position, which a lost ball returns to, is not guessed: a shot c
 * that is lost with probability p and otherwise costs A on average (over all draws) is worth
 * (A + 2p) / (1 − p) if it is played again after each loss, and the position is worth the least of
 * these (the stationary value of the best shot found). So a hole-in-one attempt that drowns half the
 * time pays for every retry.
 *
 * <p>Only hole-in-one attempts, putts that see the hole and lay-ups the noise makes fragile are
 * open to replacement ({@link #worthSearching}). The planner's shot stands unless another is better
 * by {@link #SIGNIFICANCE} standard error of the paired difference (the luckiest of many shots would
 * win otherwise), and a replacement must, on average, rest where the value map expects
 * {@link #MIN_PROGRESS} strokes fewer than from the ball (no stroke that goes round in circles or
 * leaves the ball where it was).
 */
final class NoisyChoice {
    /** Noise draws per shot (the same draws for each); 24 and 40 chose worse (see docs/bots.md). */
    static final int SAMPLES = 64;
    /** How many standard errors of the paired difference a shot must beat the planner's by. */
    static final double SIGNIFICANCE = 1;
    /** Shots the planner simulated that are scored besides its choice. */
    static final int CANDIDATES = 12;
    /** Speeds (fractions of a hole-in-one attempt's) of the lay-ups along its line that are scored too. */
    static final double[] LAYUP_FACTORS = {0.6, 0.7, 0.8, 0.9};
    /** Pattern-search rounds (each halves the step when no neighbour is better). */
    static final int ROUNDS = 4;
    /** A lay-up is re-chosen when the noise costs it this many strokes over its noiseless end, or more ... */
    static final double FRAGILE = 0.5;
    /** ... or when at least this share of its draws is lost. */
    static final double LOST_SHARE = 0.25;
    /**
     * A replacement must, on average, rest where the value map expects this many strokes fewer than
     * from the ball: on a fast green a putt that barely moves the ball looked as good as the ball's
     * own spot (lake-bowl-fast, 30 seeds: 6.6 → 5.8 mean strokes when it was added; the bench unchanged).
     */
    static final double MIN_PROGRESS = 0.1;
    /** The most of the game's remaining budget one stroke's choice spends. */
    static final double BUDGET_SHARE = 0.2;

    /** A shot scored on every draw. */
    static final class Scored {
        final Shot shot;
        final boolean[] lost = new boolean[SAMPLES];
        /** Per draw: 1 when holed, 1 + V(end) at rest; unused where lost. */
        final double[] cost = new double[SAMPLES];
        int lostCount;
        double restCost;
        double endValue;

        Scored(Shot shot) {
            this.shot = shot;
        }

        /** Its expected strokes when a lost ball is worth 2 + w (penalty, stroke, and w from the ball). */
        double mean(double w) {
            return (restCost + lostCount * (2 + w)) / SAMPLES;
        }

        /** Its stationary value: played again after every loss. */
        double value() {
            double p = (double) lostCount / SAMPLES;
            return p >= 1 ? Double.POSITIVE_INFINITY : (restCost / SAMPLES + 2 * p) / (1 - p);
        }

        double costOn(int k, double w) {
            return lost[k] ? 2 + w : cost[k];
        }
    }

    private final BotRequest request;
    private final CountingSimulator sim;
    private final World world;
    private final ValueMap values;
    private final double x, y;
    private final double[] startX = new double[SAMPLES], startY = new double[SAMPLES];
    private final Shot[] error = new Shot[SAMPLES];
    private final double ballValue;
    private final long firstSimulation, allowance;
    private final List<Scored> scored = new ArrayList<>();
    private final Shot baseShot;
    private Scored base;

    NoisyChoice(BotRequest request, Shot baseShot, ValueMap values) {
        this.request = request;
        this.sim = request.simulator();
        this.world = request.world();
        this.values = values;
        this.baseShot = baseShot;
        this.x = request.ballX();
        this.y = request.ballY();
        SplittableRandom root = new SplittableRandom(request.seed() ^ 0x726F62757374L);
        SplittableRandom positions = root.split(), velocities = root.split();
        for (int k = 0; k < SAMPLES; k++) {
            // A zero shot takes only the error: the start and the velocity offset of draw k.
            PlayedStroke p = ShotNoise.play(request.noise(), world, x, y, Shot.of(0, 0), positions, velocities);
            startX[k] = p.x();
            startY[k] = p.y();
            error[k] = p.shot();
        }
        this.ballValue = value(x, y);
        this.firstSimulation = sim.count();
        this.allowance = Math.max(3L * SAMPLES, (long) (BUDGET_SHARE * sim.remaining()));
    }

    void search() {
        List<Shot> candidates = candidates();
        base = score(baseShot);
        if (base == null || !worthSearching()) return;
        for (Shot c : candidates) {
            if (score(c) == null) return;
        }
        double speedStep = Math.max(request.noise().velocity(), ValueMap.MIN_SIGMA);
        for (int round = 0; round < ROUNDS; round++) {
            Scored centre = leader();
            Shot s = centre.shot;
            double speed = Math.hypot(s.vx(), s.vy()), angle = Math.atan2(s.vy(), s.vx());
            if (speed == 0) return;
            double angleStep = speedStep / speed;
            boolean moved = false;
            for (double[] d : new double[][] {{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                Shot n = Shot.polar(angle + d[1] * angleStep, speed + d[0] * speedStep);
                Scored c = score(new Shot(n.vx(), n.vy(), s.vz()));
                if (c == null) return;
                if (c != centre && eligible(c) && c.value() < centre.value()) moved = true;
            }
            if (!moved) speedStep /= 2;
        }
    }

    /**
     * Whether the planner's shot is open to replacement: a hole-in-one attempt, a putt the value map
     * sees straight at the hole, or a lay-up the noise makes fragile (by the value map: its expected
     * strokes are {@link #FRAGILE} over its noiseless end's, or it is lost {@link #LOST_SHARE} of
     * the time). A sound lay-up stands: the value map counts the planner's straight putts, not its
     * banks and curves, and re-choosing every lay-up by it cost strokes on the mazes (docs/bots.md).
     */
    private boolean worthSearching() {
        ShotResult planned = sim.knownResult(sim.limit(baseShot));
        if (planned != null && CountingSimulator.holed(planned)) return true;
        if (values.puttable(x, y)) return true;
        if (base.lostCount >= LOST_SHARE * SAMPLES) return true;
        double noiseless = planned == null ? Double.NaN : planned.outcome().isPenalty() ? 2 + ballValue
                : CountingSimulator.holed(planned) ? 1 : 1 + value(planned.endX(), planned.endY());
        return base.mean(ballValue) >= noiseless + FRAGILE;
    }

    /** The shot to play: the best scored, if clearly better than the planner's; else the planner's. */
    Shot best() {
        if (base == null) return baseShot;
        double w = stationary();
        Scored best = base;
        for (Scored c : scored) {
            if (eligible(c) && c.mean(w) < best.mean(w)) best = c;
        }
        return best == base || !clearlyBetter(best, base, w) ? baseShot : best.shot;
    }

    /** The best scored so far by stationary value (the pattern search's centre). */
    private Scored leader() {
        Scored best = base;
        for (Scored c : scored) {
            if (eligible(c) && c.value() < best.value()) best = c;
        }
        return best;
    }

    /** The ball's value: the least stationary value of the shots scored (the value map's guess if all are lost). */
    private double stationary() {
        double w = Double.POSITIVE_INFINITY;
        for (Scored c : scored) w = Math.min(w, c.value());
        return Double.isFinite(w) ? w : ballValue;
    }

    private boolean eligible(Scored c) {
        if (c == base) return true;
        return c.lostCount < SAMPLES && c.endValue < ballValue - MIN_PROGRESS;
    }

    /**
     * The planner's choice first; then its other simulated shots from here by where they rest on
     * the value map (best first, at least σv/2 apart); for a hole-in-one attempt, softer shots along
     * its line (lay-ups short of the hole, for when the ace risks the water or the edge).
     */
    private List<Shot> candidates() {
        List<Shot> out = new ArrayList<>();
        double spread = Math.max(request.noise().velocity(), ValueMap.MIN_SIGMA) / 2;
        ShotResult planned = sim.knownResult(sim.limit(baseShot));
        boolean ace = planned != null && CountingSimulator.holed(planned);
        List<Map.Entry<Shot, ShotResult>> known = new ArrayList<>();
        for (Map.Entry<Shot, ShotResult> e : sim.knownResults().entrySet()) {
            ShotResult r = e.getValue();
            if (r.outcome().isPenalty()) continue;
            known.add(e);
        }
        known.sort(Comparator.<Map.Entry<Shot, ShotResult>>comparingDouble(e -> noiseless(e.getValue()))
                .thenComparingDouble(e -> e.getKey().vx()).thenComparingDouble(e -> e.getKey().vy()));
        List<Shot> taken = new ArrayList<>();
        taken.add(baseShot);
        for (Map.Entry<Shot, ShotResult> e : known) {
            if (out.size() >= CANDIDATES) break;
            Shot s = e.getKey();
            if (taken.stream().noneMatch(o -> Math.hypot(o.vx() - s.vx(), o.vy() - s.vy()) < spread)) {
                out.add(s);
                taken.add(s);
            }
        }
        if (ace) {
            for (double f : LAYUP_FACTORS) out.add(new Shot(baseShot.vx() * f, baseShot.vy() * f, baseShot.vz() * f));
        }
        return out;
    }

    private double value(double ex, double ey) {
        return values.fromRest(ex, ey);
    }

    private double noiseless(ShotResult r) {
        return r.outcome() == Outcome.HOLED ? 1 : 1 + values.fromRest(r.endX(), r.endY());
    }

    /** Scores a shot on every draw (once: a shot already scored is returned as it was); null when the allowance is spent. */
    private Scored score(Shot shot) {
        Shot intended = sim.limit(shot);
        for (Scored c : scored) {
            if (c.shot.equals(intended)) return c;
        }
        if (sim.count() - firstSimulation + SAMPLES > allowance) return null;
        Scored c = new Scored(intended);
        double endValues = 0;
        for (int k = 0; k < SAMPLES; k++) {
            Shot e = error[k];
            Shot played = sim.limit(new Shot(intended.vx() + e.vx(), intended.vy() + e.vy(),
                    intended.isPutt() ? 0 : Math.max(0, intended.vz() + e.vz())));
            ShotResult r = sim.simulate(startX[k], startY[k], played);
            if (r.outcome().isPenalty()) {
                c.lost[k] = true;
                c.lostCount++;
            } else {
                double v = r.outcome() == Outcome.HOLED ? 0 : value(r.endX(), r.endY());
                c.cost[k] = 1 + v;
                c.restCost += 1 + v;
                endValues += v;
            }
        }
        c.endValue = c.lostCount == SAMPLES ? Double.POSITIVE_INFINITY : endValues / (SAMPLES - c.lostCount);
        scored.add(c);
        return c;
    }

    /** Whether {@code a} costs less than {@code b} by {@link #SIGNIFICANCE} standard errors of the paired mean. */
    static boolean clearlyBetter(Scored a, Scored b, double w) {
        double[] da = new double[SAMPLES], db = new double[SAMPLES];
        for (int k = 0; k < SAMPLES; k++) {
            da[k] = a.costOn(k, w);
            db[k] = b.costOn(k, w);
        }
        return clearlyBetter(da, db);
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
