package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.bot.play.Bots;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Every bot can sit at the game's table; the planner is the default. */
class BotCatalogTest {
    @Test
    void registersEveryBotWithThePlannerFirst() {
        List<String> names = BotCatalog.names();
        assertEquals(Bots.DEFAULT, names.get(0), "the first entry is what new bot players and Test bot start with");
        assertTrue(names.containsAll(Bots.names()), names.toString());
        assertTrue(names.contains("straight"));
        for (String name : names) {
            ShotPlanner planner = BotCatalog.planner(name);
            assertNotNull(planner, name);
            assertEquals(name, planner.name());
        }
    }

    @Test
    void theDefaultBotHolesOutThroughTheGamesInterface() throws Exception {
        World world = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "bench", "maze-c.json"));
        ShotPlanner planner = BotCatalog.planner(BotCatalog.names().get(0));
        double x = world.course().start().x(), y = world.course().start().y();
        double[] v = planner.plan(world, SimulationSettings.DEFAULT, x, y, 0, 1, new ShotPlanner.Control() {
            public void progress(double fraction, String message) {
            }

            public boolean isCancelled() {
                return false;
            }

            public void whenCancelled(Runnable action) {
            }
        });
        assertEquals(3, v.length, "(vx, vy, vz): the game plays chips too");
        assertEquals(Outcome.HOLED, new Simulator(world, SimulationSettings.DEFAULT).simulate(x, y, v[0], v[1], v[2]).outcome());
    }

    @Test
    void plannerAcesGetsTheFullSearchsBudgetInTheGame() {
        // From 500,000 the planner searches fully (PlannerBot.FULL_SEARCH_BUDGET): planner-aces in the
        // game gets that and more; every other bot, the planner included, keeps 20,000 a stroke.
        assertEquals(1_000_000, BotCatalog.budgetPerStroke("planner-aces"));
        assertTrue(BotCatalog.budgetPerStroke("planner-aces") >= minigolf.bot.planner.PlannerBot.FULL_SEARCH_BUDGET);
        for (String name : List.of("planner", "robust", "graph", "astar")) assertEquals(20_000, BotCatalog.budgetPerStroke(name));
    }
}
