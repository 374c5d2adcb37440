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

/** Every bot can sit at the game's table; the opponents by level come first. */
class BotCatalogTest {
    @Test
    void registersEveryBotWithTheLevelsFirstThenThePlanner() {
        List<String> names = BotCatalog.names();
        assertEquals(List.of("easy", "medium", "hard", "pro", Bots.DEFAULT), names.subList(0, 5),
                "a player chooses an opponent by level; the algorithms follow for experts");
        assertEquals(BotCatalog.levels(), names.subList(0, 4));
        assertTrue(BotCatalog.levels().contains(BotCatalog.DEFAULT_OPPONENT));
        assertEquals(List.of("Easy", "Medium", "Hard", "Pro", "planner"),
                names.subList(0, 5).stream().map(BotCatalog::label).toList());
        assertTrue(names.containsAll(Bots.names()), names.toString());
        assertEquals(names.size(), new java.util.HashSet<>(names).size(), "each bot once: " + names);
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
        ShotPlanner planner = BotCatalog.planner(Bots.DEFAULT);
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
