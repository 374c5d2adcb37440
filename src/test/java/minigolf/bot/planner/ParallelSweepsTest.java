package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.TileCourses;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.play.Bots;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The full search with its sweeps spread over threads ({@link minigolf.bot.CountingSimulator#spreadOver})
 * plays the same game as on one: every shot, result and simulation count. On tile 8675309-29 (far
 * from the hole: the first stroke's grid of landings, the three-stroke screen cut short by its bounds,
 * then the dense sweep, the one-putt map's sweeps, the putt sweeps) at a budget that lets every
 * stage start but cuts the brute-force ones short, where a stop in the wrong place would show.
 */
class ParallelSweepsTest {
    private static final World FAR = TileCourses.generate(8675309, 30).get(29);

    private static List<String> game(int threads) {
        Playthrough.Result r = Playthrough.play(Bots.create("planner-aces"), FAR, SimulationSettings.DEFAULT, 10, 45_000,
                7, CancellationToken.none(), BotProgress.NONE, PlayConditions.NONE, threads);
        List<String> lines = new ArrayList<>();
        for (Playthrough.PlayedShot s : r.shots()) {
            lines.add(s.shot().vx() + " " + s.shot().vy() + " " + s.shot().vz() + " -> " + s.result().outcome() + " "
                    + s.result().endX() + " " + s.result().endY() + " after " + s.simulations());
        }
        lines.add("holed " + r.holed() + " in " + r.strokes() + ", " + r.simulations() + " simulations");
        return lines;
    }

    @Test
    void theFullSearchPlaysTheSameGameOnOneTwoAndFourThreads() {
        List<String> one = game(1);
        long simulations = Long.parseLong(one.get(one.size() - 1).replaceAll(".*, (\\d+) simulations", "$1"));
        // Measured: 19,607 on the first stroke (the grid of landings and the three-stroke screen), holed in 3.
        assertTrue(simulations > 10_000, one.toString());
        assertEquals(one, game(2));
        assertEquals(one, game(4));
    }

    /**
     * The three-stroke screen cut short by its bounds in the middle of a landing's sweep (its 0.75 share of
     * 20,000 beyond the reserve): the same landings screened, simulations, look-aheads and shots kept.
     */
    @Test
    void theScreenStopsAtTheSameShotOnAnyNumberOfThreads() {
        String one = screen(1);
        // Measured on one thread (as ThreeStrokesTest): 12,437 simulations, 34 of the 198 landings screened.
        assertTrue(one.contains(" + 12437 simulations, screened 34,"), one);
        assertEquals(one, screen(2));
        assertEquals(one, screen(4));
    }

    private static String screen(int threads) {
        CountingSimulator sim = new CountingSimulator(FAR, SimulationSettings.DEFAULT, ThreeStrokes.RESERVE + 20_000,
                CancellationToken.none(), BotProgress.NONE);
        sim.spreadOver(threads);
        CourseMaps maps = new CourseMaps(true);
        maps.prepare(FAR, CancellationToken.none());
        StrokePlan plan = new StrokePlan(FAR, maps.grid(), CancellationToken.none());
        Stroke s = new Stroke(new ArrayList<>(), sim, sim, maps, FAR.course().start().x(), FAR.course().start().y(), () -> plan);
        OnePuttMap map = OnePuttMap.build(s.probe);
        TwoStrokeSearch grid = new TwoStrokeSearch(s, map);
        grid.sweepLandings();
        long before = sim.count();
        ThreeStrokes three = new ThreeStrokes(s, map);
        Shot first = three.search(grid.landings());
        StringBuilder kept = new StringBuilder();
        for (Solved k : s.solved) kept.append(k.x()).append(',').append(k.y()).append(':').append(k.shot()).append(' ');
        return grid.landings().size() + " landings, " + before + " + " + (sim.count() - before) + " simulations, screened "
                + three.screened + ", looked ahead " + three.lookedAhead + ", first " + first + ", kept " + kept;
    }
}
