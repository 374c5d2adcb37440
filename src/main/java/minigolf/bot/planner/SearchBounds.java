package minigolf.bot.planner;

import minigolf.bot.CountingSimulator;

/**
 * What one of the full search's brute-force stages ({@link TwoStrokeSearch}, {@link ThreeStrokes})
 * may spend from where it starts: at most a number of simulations, always leaving a reserve of the
 * budget to the strokes after it (so at the game's usual 20,000 such a stage does not run). Every
 * stage checks its bounds before each simulation.
 *
 * <p>Simulations only, never the clock: a bot's shots depend on its inputs (course, ball, seed,
 * budget) alone, however loaded the machine. (These bounds once also held a share of the time the
 * token had left, at most 20-30 s, so the same game gave other shots on a busy machine.) A caller
 * that must answer in time (the game) sets the token's time limit; when it runs out the bot plays
 * its best shot so far, which is the caller's choice and no part of the bot's result.
 */
final class SearchBounds {
    /** Below this many simulations to spend a stage does not start. */
    static final long MIN_SIMULATIONS = 10_000;

    private final CountingSimulator sim;
    private final long start, simulations, limit;

    /** At most {@code maxSimulations} from where {@code sim} stands, leaving {@code reserve} of its budget. */
    SearchBounds(CountingSimulator sim, long maxSimulations, long reserve) {
        this(sim.count(), Math.min(maxSimulations, sim.remaining() - reserve), sim);
    }

    private SearchBounds(long start, long simulations, CountingSimulator sim) {
        this.sim = sim;
        this.start = start;
        this.simulations = simulations;
        this.limit = start + simulations;
    }

    /** The first {@code fraction} of these bounds (a stage's first part). */
    SearchBounds first(double fraction) {
        return new SearchBounds(start, (long) (fraction * simulations), sim);
    }

    /** Whether enough is left for the stage to start. */
    boolean affordable() {
        return limit - sim.count() >= MIN_SIMULATIONS;
    }

    /** Whether the stage may simulate once more. */
    boolean inBounds() {
        return sim.count() < limit;
    }
}
