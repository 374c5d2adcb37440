package minigolf.bot.search;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Every search bot, not only the planner, plays through the air where the ground is cut off
 * (courses/chips: PlannerChipTest shows no putt from the start holes there). Measured: each holes
 * each course in 2 strokes, the fewest the chip sweep finds.
 */
class SearchBotChipTest {
    @ParameterizedTest
    @ValueSource(strings = {"grid", "local", "newton", "swarm", "astar", "astar-newton", "astar-swarm", "graph"})
    void everySearchBotChipsIntoAHoleNoPuttReaches(String bot) throws Exception {
        for (String course : new String[] {"island-green", "walled-green", "chip-wall"}) {
            World world = World.load(Path.of("courses/chips/" + course + ".json"));
            Playthrough.Result r = Playthrough.play(Bots.create(bot), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                    CancellationToken.none(), BotProgress.NONE);
            assertTrue(r.holed(), bot + " on " + course + ": " + r);
            assertEquals(2, r.strokes(), bot + " on " + course);
            assertTrue(r.shots().get(0).shot().vz() > 0, bot + " on " + course + ": the first stroke is a chip");
            assertTrue(r.botErrors().isEmpty(), r.botErrors().toString());
        }
    }

    @Test
    void whereOnlyPuttsArePlayedNoBotChips() throws Exception {
        World world = World.load(Path.of("courses/chips/island-green.json"));
        CountingSimulator sim = new CountingSimulator(world, SimulationSettings.DEFAULT, 20_000, CancellationToken.none(),
                BotProgress.NONE);
        sim.allowPuttsOnly();
        Shot shot = Bots.create("astar").nextShot(new BotRequest(sim, world.course().start().x(),
                world.course().start().y(), 0, 1));
        assertEquals(0, shot.vz(), "a putt");
    }
}
