package minigolf.bot.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.Shot;
import org.junit.jupiter.api.Test;

/** The pricing of a lost ball and the paired comparison, against their closed forms. */
class NoisyChoiceTest {
    /** A shot that holes on a share {@code made} of the draws and is lost on the rest. */
    private static NoisyChoice.Scored aceOrLost(double made) {
        NoisyChoice.Scored c = new NoisyChoice.Scored(Shot.of(1, 0));
        int holed = (int) Math.round(made * NoisyChoice.SAMPLES);
        for (int k = 0; k < NoisyChoice.SAMPLES; k++) {
            if (k < holed) {
                c.cost[k] = 1;
                c.restCost += 1;
            } else {
                c.lost[k] = true;
                c.lostCount++;
            }
        }
        return c;
    }

    /**
     * Played again after every loss, a shot that holes with probability q takes 1/q tries and
     * (1 − q)/q penalties: 1/q + (1 − q)/q strokes (the geometric series), which the stationary
     * value must give, and which is also the fixed point of its mean with a loss worth 2 + itself.
     */
    @Test
    void aLostBallCostsEveryRetry() {
        for (double q : new double[] {0.25, 0.5, 0.75, 1}) {
            NoisyChoice.Scored c = aceOrLost(q);
            double expected = 1 / q + (1 - q) / q;
            assertEquals(expected, c.value(), 1e-12, "q " + q);
            assertEquals(expected, c.mean(expected), 1e-12, "fixed point, q " + q);
        }
        assertEquals(Double.POSITIVE_INFINITY, aceOrLost(0).value());
    }

    /** The paired test: a constant one-stroke saving is clear; a difference that is mostly luck is not. */
    @Test
    void onlyAClearDifferenceReplacesThePlannersShot() {
        int n = NoisyChoice.SAMPLES;
        double[] planner = new double[n], better = new double[n], lucky = new double[n];
        for (int k = 0; k < n; k++) {
            planner[k] = 2 + (k % 2);
            better[k] = planner[k] - 1;
            // Half the draws 2 strokes better, half 1.9 worse: mean 0.05 better, spread 1.95.
            lucky[k] = planner[k] + (k % 2 == 0 ? -2 : 1.9);
        }
        assertTrue(NoisyChoice.clearlyBetter(better, planner));
        assertFalse(NoisyChoice.clearlyBetter(lucky, planner));
        assertFalse(NoisyChoice.clearlyBetter(planner, planner));
    }
}
