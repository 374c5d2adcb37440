package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** What every bot must do: hole a simple course, respect the budget, repeat itself with a seed. */
class AllBotsTest {
    static List<String> bots() {
        return Bots.names();
    }

    /** The bots by algorithm and the opponents by level. */
    static List<String> allBots() {
        return Bots.allNames();
    }

    private static Playthrough.Result play(String bot, World world, long budget, long seed) {
        Bot b = Bots.create(bot);
        assertNotNull(b, bot);
        assertEquals(bot, b.name());
        return Playthrough.play(b, world, SimulationSettings.DEFAULT, 10, budget, seed, CancellationToken.none(),
                BotProgress.NONE);
    }

    @ParameterizedTest
    @MethodSource("bots")
    void holesTheFlatSevenMetreCourse(String bot) {
        Playthrough.Result r = play(bot, BenchCourses.load("flat-7m"), 200_000, 3);
        assertTrue(r.holed(), bot + " did not hole flat-7m: " + r);
        assertTrue(r.strokes() <= 3, bot + " took " + r.strokes() + " strokes");
        // Every stroke's count adds up to the game's count.
        assertEquals(r.simulations(), r.shots().stream().mapToLong(Playthrough.PlayedShot::simulations).sum());
    }

    @ParameterizedTest
    @MethodSource("allBots")
    void neverExceedsTheBudget(String bot) {
        // The lake defeats several bots: they must stop at the budget, not run on.
        for (long budget : new long[] {1, 7, 60}) {
            Playthrough.Result r = play(bot, BenchCourses.load("lake-bowl"), budget, 5);
            assertTrue(r.simulations() <= budget, bot + " used " + r.simulations() + " of " + budget);
            assertTrue(r.shots().size() >= 1, "a shot is played even when the budget runs out");
        }
    }

    @ParameterizedTest
    @MethodSource("allBots")
    void theSameSeedGivesTheSameShots(String bot) {
        World world = BenchCourses.load("pond");
        Playthrough.Result a = play(bot, world, 3_000, 11), b = play(bot, world, 3_000, 11);
        assertEquals(a.simulations(), b.simulations());
        assertEquals(a.shots().size(), b.shots().size());
        for (int i = 0; i < a.shots().size(); i++) {
            assertEquals(a.shots().get(i).shot(), b.shots().get(i).shot(), bot + " stroke " + i);
        }
    }
}
