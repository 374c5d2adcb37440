package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The planner's budget decides its search: the quick plan below {@link PlannerBot#FULL_SEARCH_BUDGET}, the full one from it. */
class PlannerSearchTierTest {
    private static Playthrough.Result play(PlannerBot bot, World world, long budget) {
        // No time limit: the game depends on the budget alone (SearchBounds), however loaded the machine.
        return Playthrough.play(bot, world, SimulationSettings.DEFAULT, 10, budget, 1, CancellationToken.none(),
                BotProgress.NONE);
    }

    @Test
    void theBudgetChoosesTheQuickPlanOrTheFullSearch() throws Exception {
        // maze-c-hills: two strokes either way; the full search first looks densely for a hole-in-one.
        World world = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "bench", "maze-c-hills.json"));
        PlannerBot quick = new PlannerBot();
        Playthrough.Result q = play(quick, world, 20_000);
        assertFalse(quick.searchesFully());
        PlannerBot full = new PlannerBot();
        Playthrough.Result f = play(full, world, PlannerBot.FULL_SEARCH_BUDGET);
        assertTrue(full.searchesFully());
        PlannerBot aces = new PlannerBot(true);
        Playthrough.Result a = play(aces, world, 20_000);
        assertTrue(aces.searchesFully(), "planner-aces searches fully at any budget");

        assertEquals(2, q.strokes());
        assertEquals(2, f.strokes());
        // The bench table's figures: 167 simulations for the quick plan, 2,034 for the full search
        // (its dense sweep alone is 1,080), the same at either budget since no stage needs more.
        assertEquals(167, q.simulations());
        assertEquals(2034, f.simulations());
        assertEquals(f.simulations(), a.simulations());
        assertEquals(f.shots().get(0).shot(), a.shots().get(0).shot(), "the full search plays planner-aces' shots");
    }
}
