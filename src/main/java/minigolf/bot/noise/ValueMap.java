package minigolf.bot.noise;

import minigolf.bot.NoiseModel;
import minigolf.bot.map.DistanceField;
import minigolf.bot.planner.StrokePlan;
import minigolf.bot.search.SpeedGuess;
import minigolf.course.HoleRule;
import minigolf.physics.World;

/**
 * Expected strokes to hole out from a resting ball under the noise, for {@link RobustBot}; no
 * simulation, so it can score every noise draw of every candidate shot.
 * <ul>
 * <li>Where a straight putt sees the hole clear of water within a maximum-speed roll (the
 *     planner's {@link StrokePlan#putt}): 1 + (1 − p)(1 + {@value #MISS_EXTRA}), p the make
 *     probability of that putt aimed at the middle of the hole ({@link #makeProbability}), a miss
 *     leaving a short putt that itself holes most of the time.</li>
 * <li>Elsewhere: the stroke plan's straight putts to the hole (k) plus {@value #LAST_PUTT_EXTRA}
 *     for the last putt, which is rarely short.</li>
 * <li>Where the plan sees no way: 2 plus the distance field's length in maximum-speed rolls, or
 *     {@value #NO_PATH} where the ground does not reach the hole at all.</li>
 * </ul>
 */
public final class ValueMap {
    /** Strokes a missed putt still costs beyond the next one (it leaves a short putt, mostly holed). */
    static final double MISS_EXTRA = 0.15;
    /** Beyond the plan's count of straight putts: the last one from a few metres, missed about half the time. */
    static final double LAST_PUTT_EXTRA = 0.5;
    /** Where the ground does not reach the hole. */
    static final double NO_PATH = 6;
    /** The smallest velocity noise the model uses (a ball is never struck exactly). */
    static final double MIN_SIGMA = 0.01;
    /** A disc of radius r holds as much of a round Gaussian as a square of half side r·√π/2. */
    private static final double DISC_TO_SQUARE = Math.sqrt(Math.PI) / 2;

    private final World world;
    private final StrokePlan plan;
    private final DistanceField field;
    private final double sigma;
    private final double holeX, holeY, radius;
    private final boolean capture;

    public ValueMap(World world, StrokePlan plan, DistanceField field, NoiseModel noise) {
        this.world = world;
        this.plan = plan;
        this.field = field;
        this.sigma = Math.max(MIN_SIGMA, noise.velocity());
        this.holeX = world.hole().position().x();
        this.holeY = world.hole().position().y();
        this.radius = world.hole().radius();
        this.capture = world.hole().rule() == HoleRule.CAPTURE;
    }

    /** Whether a straight putt from (x, y) sees the hole clear of water within a maximum-speed roll. */
    public boolean puttable(double x, double y) {
        return plan.putt(x, y, holeX, holeY);
    }

    /** Expected strokes from a ball at rest at (x, y) to the hole. */
    public double fromRest(double x, double y) {
        if (plan.putt(x, y, holeX, holeY)) {
            return 1 + (1 - makeProbability(x, y)) * (1 + MISS_EXTRA);
        }
        int k = plan.strokesAt(x, y);
        if (k != Integer.MAX_VALUE) return k + LAST_PUTT_EXTRA;
        double d = field.at(x, y);
        if (!Double.isFinite(d)) return NO_PATH;
        return Math.min(NO_PATH, 2 + d / SpeedGuess.maxRoll(world, x, y, holeX, holeY));
    }

    /**
     * The chance that a straight putt from (x, y), aimed at the middle of the success region,
     * holes under velocity noise σ per component. The along-line error of the speed and the
     * lateral one are independent N(0, σ); with a = v²/2d the ball's mean deceleration (the
     * bots' energy guess {@link SpeedGuess}, slope included), the speeds that hole are
     * [√(2a(d−w)), √(2a(d+w))] for the rest rule (w = r·√π/2: the disc as a square of the same
     * area) and [√(2a(d−w)), √(2ad + vc²)] for the capture rule (crossing the centre slower than
     * the capture speed vc); the lateral speed must stay within v·w/d (the angle w/d; 0.7 of it for
     * the capture rule, whose window narrows off the centre). p = erf(half speed window / σ√2) ·
     * erf(lateral window / σ√2). Checked against the engine in {@code ValueMapTest}.
     */
    public double makeProbability(double x, double y) {
        double d = Math.hypot(holeX - x, holeY - y);
        double w = radius * DISC_TO_SQUARE;
        if (d <= w) return 1;
        double v = SpeedGuess.speed(world, x, y, d, holeX, holeY, 1e-6);
        double a = v * v / (2 * d);
        double low = Math.sqrt(2 * a * (d - w));
        double high = capture ? Math.sqrt(2 * a * d + Math.pow(world.hole().effectiveCaptureSpeed(), 2))
                : Math.sqrt(2 * a * (d + w));
        double lateral = (capture ? 0.7 : 1) * v * w / d;
        double s = sigma * Math.sqrt(2);
        return erf((high - low) / 2 / s) * erf(lateral / s);
    }

    /** The error function (Abramowitz and Stegun 7.1.26, error below 1.5e-7). */
    static double erf(double z) {
        double t = 1 / (1 + 0.3275911 * Math.abs(z));
        double y = 1 - t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))))
                * Math.exp(-z * z);
        return z >= 0 ? y : -y;
    }
}
