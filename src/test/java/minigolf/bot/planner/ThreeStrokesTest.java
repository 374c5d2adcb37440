package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
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
 * {@link ThreeStrokes} on the two tiles it was built on (so 8675309 and 20261124 are tuning seeds now,
 * no longer held out) where planner-aces took two strokes more than the
 * exhaustive search (issue 13): 8675309-29 (the first stroke is far from the hole; it laid up by the
 * plan and needed 4 more) and 20261124-36 (no two strokes; the lay-up nearest the hole rested in sand).
 */
class ThreeStrokesTest {
    private static final World FAR = TileCourses.generate(8675309, 30).get(29);
    private static final World NEAR = TileCourses.generate(20261124, 37).get(36);

    private static Stroke atStart(World w, long budget) {
        CountingSimulator sim = new CountingSimulator(w, SimulationSettings.DEFAULT, budget, CancellationToken.none(),
                BotProgress.NONE);
        // The field planner-aces routes on (friction-aware): the landings are screened nearest it first.
        CourseMaps maps = new CourseMaps(true);
        maps.prepare(w, CancellationToken.none());
        StrokePlan plan = new StrokePlan(w, maps.grid(), CancellationToken.none());
        return new Stroke(new ArrayList<>(), sim, sim, maps, w.course().start().x(), w.course().start().y(), () -> plan);
    }

    /** The kept shot from (x, y), or null. */
    private static Shot kept(Stroke s, double x, double y) {
        for (Solved k : s.solved) if (k.x() == x && k.y() == y) return k.shot();
        return null;
    }

    @Test
    void itFindsALandingWhoseKeptLayupAndPuttHoleOnTheEngine() {
        Stroke s = atStart(FAR, 1_000_000);
        OnePuttMap map = OnePuttMap.build(s.probe);
        TwoStrokeSearch grid = new TwoStrokeSearch(s, map);
        assertNull(grid.sweepLandings());
        assertFalse(grid.landings().isEmpty());
        long before = s.sim.count();
        ThreeStrokes three = new ThreeStrokes(s, map);
        Shot first = three.search(grid.landings());
        assertNotNull(first);
        long used = s.sim.count() - before;
        // Measured: 71,282 simulations: 198 landings screened (360 shots each: hills, two speeds), the look-ahead
        // from the best of them holes.
        assertTrue(used <= 75_000 && used <= ThreeStrokes.MAX_SIMULATIONS, used + " simulations");
        assertEquals(1, three.lookedAhead);
        // The three strokes on the engine: the landing, the kept lay-up from it, the kept putt from there
        // (each limited to the speed limit as a game plays it: a maximum-speed shot is scaled once more).
        Simulator engine = new Simulator(FAR, SimulationSettings.DEFAULT);
        Shot played = s.sim.limit(first);
        ShotResult r = engine.simulate(FAR.course().start().x(), FAR.course().start().y(), played.vx(), played.vy());
        for (int stroke = 2; stroke <= 3; stroke++) {
            assertEquals(Outcome.STOPPED, r.outcome(), "stroke " + (stroke - 1));
            Shot next = kept(s, r.endX(), r.endY());
            assertNotNull(next, "a shot kept for stroke " + stroke);
            played = s.sim.limit(next);
            r = engine.simulate(r.endX(), r.endY(), played.vx(), played.vy());
        }
        assertEquals(Outcome.HOLED, r.outcome());

        // From the landing, TwoStrokeSearch's putt sweep (none holes: the game is 3) traces the lay-ups
        // ThreeStrokes needs, so MapTwoStrokes' look-ahead from them sweeps no more (its own sweep: 360 shots).
        ShotResult landing = engine.simulate(FAR.course().start().x(), FAR.course().start().y(),
                s.sim.limit(first).vx(), s.sim.limit(first).vy());
        Stroke from = new Stroke(new ArrayList<>(), s.sim, s.probe, s.maps, landing.endX(), landing.endY(), s.plan);
        MapTwoStrokes layups = new MapTwoStrokes(from, map);
        assertNull(new PuttSweep(from, layups).holeInOne());
        assertTrue(layups.hasTargets() && Double.isFinite(layups.bestScore()));
        long beforeLookAhead = s.sim.count();
        assertNotNull(layups.search(), "a lay-up from which one putt holes");
        assertTrue(s.sim.count() - beforeLookAhead < 360, (s.sim.count() - beforeLookAhead) + " simulations");
    }

    @Test
    void itSpendsNoMoreThanTheBudgetLeavesBeyondTheReserve() {
        Stroke small = atStart(FAR, ThreeStrokes.RESERVE + SearchBounds.MIN_SIMULATIONS - 1);
        ThreeStrokes none = new ThreeStrokes(small, null);
        assertFalse(none.affordable(), "the game's usual budget leaves it out");
        assertNull(none.search(new ArrayList<>()));
        assertEquals(0, small.sim.count());

        long budget = ThreeStrokes.RESERVE + 20_000;
        Stroke s = atStart(FAR, budget);
        OnePuttMap map = OnePuttMap.build(s.probe);
        TwoStrokeSearch grid = new TwoStrokeSearch(s, map);
        grid.sweepLandings();
        long before = s.sim.count(), share = s.sim.remaining() - ThreeStrokes.RESERVE;
        ThreeStrokes three = new ThreeStrokes(s, map);
        assertTrue(three.affordable());
        three.search(grid.landings());
        long used = s.sim.count() - before;
        // The screen stops at its share (0.75); the look-ahead checks before each landing, so it goes over by one
        // landing's look-ahead at most. Measured: 12,437 of 16,580 (34 landings screened, one looked ahead from).
        assertTrue(used <= share + 2_000, used + " of " + share + " simulations");
        assertTrue(three.screened > 0);
    }

    @Test
    void plannerAcesPlaysBothTilesInThreeWithALargeBudget() {
        for (World w : new World[] {FAR, NEAR}) {
            // No time limit: the game depends on the budget alone (SearchBounds), however loaded the machine.
            Playthrough.Result r = Playthrough.play(Bots.create("planner-aces"), w, SimulationSettings.DEFAULT, 10,
                    1_000_000, 1, CancellationToken.none(), BotProgress.NONE);
            assertTrue(r.holed(), w.course().name());
            // Measured: 74,702 and 324,172 simulations (both 5 strokes before ThreeStrokes; the exhaustive search's games are 3).
            assertEquals(3, r.strokes(), w.course().name());
        }
    }
}
