package minigolf.physics.reference;

/**
 * How well a shot's end point is determined by the shot: the reference run again with each
 * component of the velocity changed by ±{@value #PERTURBATION} m/s, and the largest distance of
 * those four end points from the shot's own. A shot whose reference end point moves by more than
 * {@value #ILL_CONDITIONED_SPREAD} m under so small a change has no 1 mm answer: after several
 * obstacle contacts the path has split (a wall's corner, a ball that just reaches or misses the
 * water), and no integrator can be held to 1 mm there (docs/measurements.md, "Accuracy against an independent
 * reference"). This is a property of the shot and the model, measured with the reference alone.
 */
public final class Conditioning {
    /** The change of each velocity component (m/s), far below anything a player or a bot can aim. */
    public static final double PERTURBATION = 1e-7;
    /** A spread above this (m) makes the shot ill-conditioned for a 1 mm comparison. */
    public static final double ILL_CONDITIONED_SPREAD = 1e-3;

    private Conditioning() {
    }

    /**
     * The largest distance (m) between the reference's end point for the shot, {@code base}, and
     * its end points for the four perturbed shots; infinite if one of them is not covered. Shots
     * are rolling shots from (x0, y0) with velocity (vx, vy).
     */
    public static double spread(ReferenceSimulator reference, double x0, double y0, double vx, double vy,
                                ReferenceResult base) {
        return spread(reference, 0, x0, y0, vx, vy, base);
    }

    /** As above, the shots played at course clock {@code clock} (moving obstacles). */
    public static double spread(ReferenceSimulator reference, double clock, double x0, double y0, double vx, double vy,
                                ReferenceResult base) {
        double worst = 0;
        for (int k = 0; k < 4; k++) {
            double d = (k % 2 == 0 ? 1 : -1) * PERTURBATION;
            ReferenceResult r = k < 2
                    ? reference.simulateAt(clock, x0, y0, vx + d, vy, 0)
                    : reference.simulateAt(clock, x0, y0, vx, vy + d, 0);
            if (!r.covered()) return Double.POSITIVE_INFINITY;
            worst = Math.max(worst, Math.hypot(r.endX() - base.endX(), r.endY() - base.endY()));
        }
        return worst;
    }

    /** Whether the shot's reference end point spreads by more than {@value #ILL_CONDITIONED_SPREAD} m. */
    public static boolean illConditioned(double spread) {
        return spread > ILL_CONDITIONED_SPREAD;
    }
}
