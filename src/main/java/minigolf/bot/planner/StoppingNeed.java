package minigolf.bot.planner;

/**
 * The speed² a shot in one path's direction needs to stop at each point of that path, worked out
 * forwards from what one shot along it lost on the way (friction and slopes: the same on flat
 * ground for any speed), each cushion dividing what comes after it by the share of the speed² it
 * kept. {@link MapTwoStrokes}' lay-ups and {@link PuttSweep}'s passes by the hole both use it.
 */
final class StoppingNeed {
    private double lastV2, need, kept = 1;
    /** A cushion since the last step: the speed² just before and just after it. */
    private double before2 = Double.NaN, after2;

    /** Along a shot played at this speed. */
    StoppingNeed(double speed) {
        lastV2 = speed * speed;
    }

    /** A step of the shot ended at speed² {@code v2}: the need there. */
    double step(double v2) {
        if (Double.isNaN(before2)) {
            need += (lastV2 - v2) / kept;
        } else {
            need += (lastV2 - before2) / kept;
            kept *= Math.max(after2 / Math.max(before2, 1e-12), 1e-3);
            need += (after2 - v2) / kept;
            before2 = Double.NaN;
        }
        lastV2 = v2;
        return need;
    }

    /** The shot hit a cushion (the first of a step's cushions sets the speed before). */
    void cushion(double speedBefore, double speedAfter) {
        if (Double.isNaN(before2)) before2 = speedBefore * speedBefore;
        after2 = speedAfter * speedAfter;
    }

    /** The speed² at the end of the last step. */
    double lastV2() {
        return lastV2;
    }

    /** The share of the speed² the cushions so far have kept. */
    double kept() {
        return kept;
    }
}
