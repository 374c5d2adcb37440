package minigolf.bot.noise;

import minigolf.bot.map.DistanceField;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;

/**
 * The expected strokes of one played outcome under noise, for {@link RobustBot}: 1 for the stroke
 * itself, plus a guess of the strokes still to come from where the ball ends. The guess is a model,
 * not a search: from a distance d (along the water-avoiding distance field) the next putt holes
 * with probability e^(-d/L), L = {@value #HOLE_SCALE} / σv metres (about the make rates measured
 * under velocity noise: a 7 m putt holes ~37% at σv = 0.05); a miss costs one more; every full
 * roll of {@code reach} beyond the first costs another. A lost ball costs its penalty and the
 * strokes from where it lay.
 */
final class StrokeCost {
    /** Metres times m/s: L = HOLE_SCALE / σv (see the class comment). */
    static final double HOLE_SCALE = 0.35;
    /** The guess where the distance field sees no way to the hole. */
    static final double NO_PATH = 6;
    /** The smallest velocity noise the model uses (it is never exact). */
    static final double MIN_SIGMA = 0.01;

    private final DistanceField field;
    private final double holeScale;
    private final double reach;

    StrokeCost(DistanceField field, NoiseModel noise, double reach) {
        this.field = field;
        this.holeScale = HOLE_SCALE / Math.max(MIN_SIGMA, noise.velocity());
        this.reach = Math.max(reach, 1e-3);
    }

    /** Expected strokes from (x, y) to the hole. */
    double fromRest(double x, double y) {
        double d = field.at(x, y);
        if (!Double.isFinite(d)) return NO_PATH;
        return 1 + (1 - Math.exp(-d / holeScale)) + Math.floor(d / reach);
    }

    /** Expected strokes of a stroke with this result, played from where the ball lay at (x, y). */
    double of(ShotResult r, double x, double y) {
        if (r.outcome() == Outcome.HOLED) return 1;
        if (r.outcome().isPenalty()) return 2 + fromRest(x, y);
        return 1 + fromRest(r.endX(), r.endY());
    }
}
