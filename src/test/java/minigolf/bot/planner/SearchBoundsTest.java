package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.TileCourses;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The full search's bounds are simulations, never the clock (issue 29): the same game on a machine
 * as slow as one likes plays the same shots with the same simulations. The slow machine is a token
 * clock that runs 10 ms a read (the search on tuning tile 5150-25, {@link TwoStrokeSearchTest}, reads
 * it tens of thousands of times, minutes of its time; the token's time limit, a day, never ends) and
 * a stall of 31 s of real time as the two-stroke search starts. With the bounds of before (0.4 of the
 * time left, at most 30 s of real time) the stall ended the two-stroke search before its first
 * simulation, and the game took 3 strokes instead of 2.
 */
class SearchBoundsTest {
    private static final World TILE = TileCourses.generate(5150, 26).get(25);

    /** Longer than any bound the searches had in seconds (30). */
    private static final long STALL_MILLIS = 31_000;

    private static Playthrough.Result play(CancellationToken token, BotProgress progress) {
        return Playthrough.play(Bots.create("planner-aces"), TILE, SimulationSettings.DEFAULT, 10, 1_000_000, 1, token,
                progress);
    }

    private static List<Object> shots(Playthrough.Result r) {
        return r.shots().stream().map(s -> (Object) List.of(s.shot(), s.simulations())).toList();
    }

    @Test
    void aSlowMachinePlaysTheSameShotsWithTheSameSimulations() {
        Playthrough.Result quick = play(CancellationToken.none(), BotProgress.NONE);

        AtomicLong reads = new AtomicLong();
        CancellationToken slow = new CancellationToken(() -> reads.incrementAndGet() * 10_000_000L);
        slow.limitTime(86_400);
        AtomicBoolean stalled = new AtomicBoolean();
        BotProgress stall = (simulations, budget, phase) -> {
            if (phase.equals("two-stroke search") && !stalled.getAndSet(true)) {
                try {
                    Thread.sleep(STALL_MILLIS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
        Playthrough.Result slowed = play(slow, stall);

        assertTrue(quick.holed());
        assertEquals(2, quick.strokes(), "the two-stroke search's game");
        assertEquals(shots(quick), shots(slowed));
        assertEquals(quick.simulations(), slowed.simulations());
        assertFalse(slowed.timedOut());
        assertTrue(stalled.get(), "the two-stroke search ran");
        // The slow clock ran far past any bound a search once had (30 s), without reaching the limit.
        double clockSeconds = reads.get() * 0.01;
        assertTrue(clockSeconds > 120 && clockSeconds < 86_400, clockSeconds + " s on the slow clock");
    }

    @Test
    void theBoundsAreSimulationsLeavingTheReserve() {
        CountingSimulator sim = new CountingSimulator(TILE, SimulationSettings.DEFAULT, TwoStrokeSearch.RESERVE + 20_000,
                CancellationToken.none(), BotProgress.NONE);
        SearchBounds bounds = new SearchBounds(sim, 300_000, TwoStrokeSearch.RESERVE);
        assertTrue(bounds.affordable());
        SearchBounds first = bounds.first(0.1);
        double x = TILE.course().start().x(), y = TILE.course().start().y();
        for (int i = 0; i < 2_000; i++) {
            assertTrue(first.inBounds(), "simulation " + i);
            sim.simulate(x, y, Shot.polar(0.01 * i, 0.3));
        }
        assertFalse(first.inBounds(), "a tenth of 20,000");
        assertTrue(bounds.inBounds() && bounds.affordable(), "18,000 left");
        assertFalse(new SearchBounds(sim, 300_000, TwoStrokeSearch.RESERVE + 8_001).affordable(),
                "9,999 left beyond the reserve: below " + SearchBounds.MIN_SIMULATIONS);
        assertFalse(new SearchBounds(sim, 9_999, TwoStrokeSearch.RESERVE).affordable(), "at most 9,999 to spend");
        assertTrue(new SearchBounds(sim, 10_000, TwoStrokeSearch.RESERVE).affordable());
    }
}
