package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Holes reachable only through the air (courses/chips): the planner chips (issue 12). An
 * independent check first shows no putt from the start holes there (72 directions x 10 speeds).
 */
class PlannerChipTest {
    @ParameterizedTest
    @CsvSource({
        // course, strokes the planner takes (measured: its chip sweep finds no hole-in-one there)
        "island-green, 2", "walled-green, 2", "chip-wall, 2"})
    void thePlannerChipsWhereNoPuttCanHole(String name, int strokes) throws Exception {
        World world = World.load(Path.of("courses/chips/" + name + ".json"));
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double x0 = world.course().start().x(), y0 = world.course().start().y(), max = world.physics().maxSpeed();
        for (int a = 0; a < 72; a++) {
            for (int v = 1; v <= 10; v++) {
                double angle = Math.toRadians(5 * a), speed = max * v / 10;
                ShotResult r = engine.simulate(x0, y0, speed * Math.cos(angle), speed * Math.sin(angle));
                assertTrue(r.outcome() != Outcome.HOLED, name + ": a putt holes at " + 5 * a + " deg, " + speed + " m/s");
            }
        }
        for (long seed : new long[] {1, 5}) {
            Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000,
                    seed, CancellationToken.none(), BotProgress.NONE);
            assertTrue(r.holed(), name + " not holed: " + r);
            assertEquals(strokes, r.strokes(), name);
            assertTrue(r.shots().get(0).shot().vz() > 0, name + ": the first stroke is a chip");
            assertTrue(r.shots().stream().noneMatch(s -> s.result().outcome().isPenalty()), name + ": a penalty");
            assertTrue(r.botErrors().isEmpty(), r.botErrors().toString());
        }
    }

    @org.junit.jupiter.api.Test
    void whereOnlyPuttsArePlayedThePlannerDoesNotChip() throws Exception {
        // A simulator told to allow putts only (CountingSimulator.allowPuttsOnly) gets no chip.
        World world = World.load(Path.of("courses/chips/island-green.json"));
        minigolf.bot.CountingSimulator sim = new minigolf.bot.CountingSimulator(world, SimulationSettings.DEFAULT,
                100_000, CancellationToken.none(), BotProgress.NONE);
        sim.allowPuttsOnly();
        minigolf.bot.Shot shot = new PlannerBot().nextShot(new minigolf.bot.BotRequest(sim,
                world.course().start().x(), world.course().start().y(), 0, 1));
        assertEquals(0, shot.vz(), "a putt");
        minigolf.bot.CountingSimulator free = new minigolf.bot.CountingSimulator(world, SimulationSettings.DEFAULT,
                100_000, CancellationToken.none(), BotProgress.NONE);
        assertTrue(new PlannerBot().nextShot(new minigolf.bot.BotRequest(free,
                world.course().start().x(), world.course().start().y(), 0, 1)).vz() > 0, "a chip where chips are played");
    }
}
