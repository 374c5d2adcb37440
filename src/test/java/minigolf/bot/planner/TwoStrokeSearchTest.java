package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import minigolf.bot.BotCancelledException;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.TileCourses;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * {@link TwoStrokeSearch} on tuning tile course 5150-25 (never a held-out seed): a two-stroke game
 * (the exhaustive search's) whose landing the one-putt map does not mark, so no stage before it
 * finds it; planner-aces played it in 3.
 */
class TwoStrokeSearchTest {
    private static final World TILE = TileCourses.generate(5150, 26).get(25);

    private static Stroke atStart(long budget, CancellationToken token, BotProgress progress) {
        CountingSimulator sim = new CountingSimulator(TILE, SimulationSettings.DEFAULT, budget, token, progress);
        CourseMaps maps = new CourseMaps();
        maps.prepare(TILE, CancellationToken.none());
        StrokePlan plan = new StrokePlan(TILE, maps.grid(), CancellationToken.none());
        return new Stroke(new ArrayList<>(), sim, sim, maps, TILE.course().start().x(), TILE.course().start().y(),
                () -> plan);
    }

    @Test
    void itFindsALayupFromWhichItsKeptPuttHolesOnTheEngine() {
        Stroke s = atStart(Long.MAX_VALUE, CancellationToken.none(), BotProgress.NONE);
        OnePuttMap map = OnePuttMap.build(s.probe);
        long before = s.sim.count();
        Shot layup = new TwoStrokeSearch(s, map).search();
        assertNotNull(layup);
        // Measured: 12,733 simulations (its first-stroke grid is 2,700 of them; the fifth landing holes).
        long used = s.sim.count() - before;
        assertTrue(used <= 14_000, used + " simulations");
        Simulator engine = new Simulator(TILE, SimulationSettings.DEFAULT);
        ShotResult first = engine.simulate(TILE.course().start().x(), TILE.course().start().y(), layup.vx(), layup.vy());
        assertEquals(Outcome.STOPPED, first.outcome());
        Solved putt = s.solved.get(s.solved.size() - 1);
        assertEquals(first.endX(), putt.x());
        assertEquals(first.endY(), putt.y());
        assertEquals(Outcome.HOLED, engine.simulate(putt.x(), putt.y(), putt.shot().vx(), putt.shot().vy()).outcome());
    }

    @Test
    void itSpendsNoMoreThanTheBudgetLeavesBeyondTheReserve() {
        Stroke small = atStart(TwoStrokeSearch.RESERVE, CancellationToken.none(), BotProgress.NONE);
        TwoStrokeSearch none = new TwoStrokeSearch(small, null);
        assertFalse(none.affordable(), "the game's usual budget leaves it out");
        assertNull(none.search());
        assertEquals(0, small.sim.count());

        long budget = TwoStrokeSearch.RESERVE + 12_000;
        Stroke s = atStart(budget, CancellationToken.none(), BotProgress.NONE);
        TwoStrokeSearch search = new TwoStrokeSearch(s, null);
        assertTrue(search.affordable());
        assertNull(search.search(), "12,000 simulations are too few here (15,594 needed without the map: the seventh landing)");
        // It stops before a landing's putt search once its share is spent: one putt search over at most.
        assertTrue(s.sim.count() <= 12_000 + 3_000, s.sim.count() + " simulations");
        assertTrue(s.sim.remaining() >= TwoStrokeSearch.RESERVE - 3_000);
        assertTrue(search.tried > 0);
    }

    @Test
    void aCancelStopsIt() {
        CancellationToken token = CancellationToken.none();
        BotProgress cancelAt5000 = (simulations, budget, phase) -> {
            if (simulations >= 5_000) token.cancel();
        };
        Stroke s = atStart(1_000_000, token, cancelAt5000);
        assertThrows(BotCancelledException.class, () -> new TwoStrokeSearch(s, null).search());
        assertTrue(s.sim.count() <= 5_000 + CountingSimulator.PROGRESS_INTERVAL, s.sim.count() + " simulations");
    }

    @Test
    void planerAcesPlaysTheTwoStrokeGameWithALargeBudgetOnly() {
        // No time limit: the game depends on the budget alone (SearchBounds), however loaded the machine.
        Playthrough.Result large = Playthrough.play(Bots.create("planner-aces"), TILE, SimulationSettings.DEFAULT, 10,
                1_000_000, 1, CancellationToken.none(), BotProgress.NONE);
        Playthrough.Result usual = Playthrough.play(Bots.create("planner-aces"), TILE, SimulationSettings.DEFAULT, 10,
                20_000, 1, CancellationToken.none(), BotProgress.NONE);
        assertTrue(large.holed() && usual.holed());
        assertEquals(2, large.strokes());
        assertEquals(3, usual.strokes());
        // Measured 18,880 (the search about 12,700 of them).
        assertTrue(large.simulations() <= 20_000, large.simulations() + " simulations");
    }
}
