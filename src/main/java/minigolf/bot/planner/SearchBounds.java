package minigolf.bot.planner;

import minigolf.bot.CountingSimulator;

/**
 * What one of the full search's brute-force stages ({@link TwoStrokeSearch}, {@link ThreeStrokes})
 * may spend from where it starts: at most a number of simulations, always leaving a reserve of the
 * budget to the strokes after it (so at the game's usual 20,000 such a stage does not run), and a
 * share of the time the token has left, at most a number of seconds. Every stage checks its bounds
 * before each simulation.
 */
final class SearchBounds {
    /** Below this many simulations to spend a stage does not start. */
    static final long MIN_SIMULATIONS = 10_000;
    /** The share of the time left a stage may take. */
    static final double TIME_SHARE = 0.4;

    private final CountingSimulator sim;
    private final long start, simulations, startNanos;
    private final double seconds;
    private final long limit, deadline;

    SearchBounds(CountingSimulator sim, long maxSimulations, long reserve, double maxSeconds) {
        this(sim, sim.count(), Math.min(maxSimulations, sim.remaining() - reserve), System.nanoTime(),
                Math.min(maxSeconds, TIME_SHARE * sim.token().secondsLeft()));
    }

    private SearchBounds(CountingSimulator sim, long start, long simulations, long startNanos, double seconds) {
        this.sim = sim;
        this.start = start;
        this.simulations = simulations;
        this.startNanos = startNanos;
        this.seconds = seconds;
        this.limit = start + simulations;
        this.deadline = startNanos + (long) (seconds * 1e9);
    }

    /** The first {@code fraction} of these bounds, in simulations and in time (a stage's first part). */
    SearchBounds first(double fraction) {
        return new SearchBounds(sim, start, (long) (fraction * simulations), startNanos, fraction * seconds);
    }

    /** Whether enough is left for the stage to start. */
    boolean affordable() {
        return limit - sim.count() >= MIN_SIMULATIONS;
    }

    /** Whether the stage may simulate once more. */
    boolean inBounds() {
        return sim.count() < limit && System.nanoTime() - deadline < 0;
    }
}
