package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The offline fewest-strokes reference: its answers on courses whose minimum we know, replayed. */
class ExhaustiveStrokeSearchTest {
    @ParameterizedTest
    @CsvSource({
        // course, fewest strokes (flat-7m: a straight putt; two-putt: 2 proved, the hole is beyond
        // a maximum-speed roll; water-bank: the bank shot off the wall, found by a scan)
        "flat-7m, 1", "two-putt, 2", "water-bank, 1"})
    void findsTheKnownMinimumAndItsShotsReallyHole(String course, int fewest) {
        World world = BenchCourses.load(course);
        ExhaustiveStrokeSearch.Result r = ExhaustiveStrokeSearch.search(world, ExhaustiveStrokeSearch.Grid.DEFAULT);
        assertEquals(fewest, r.strokes(), course);
        assertEquals(fewest, r.shots().size());
        assertEquals(fewest, r.nodesPerLevel().size(), "levels searched");
        // Replaying the shots from the start: each rests where the next starts, the last holes.
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double x = world.course().start().x(), y = world.course().start().y();
        for (int i = 0; i < r.shots().size(); i++) {
            double[] s = r.shots().get(i);
            assertEquals(x, s[0], 1e-12);
            assertEquals(y, s[1], 1e-12);
            ShotResult result = engine.simulate(x, y, s[2], s[3]);
            assertEquals(i == r.shots().size() - 1 ? Outcome.HOLED : Outcome.STOPPED, result.outcome(), course + " shot " + i);
            assertTrue(Math.hypot(s[2], s[3]) <= world.physics().maxSpeed() + 1e-9, "within the speed limit");
            x = result.endX();
            y = result.endY();
        }
    }
}
