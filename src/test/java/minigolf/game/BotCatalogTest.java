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
    void plannerAcesGetsABudgetSizedToTheStrokesTime() {
        // planner-aces searches fully at any budget; in the game it gets the simulations its search
        // runs through in the 20 s a stroke has, at the rate measured (docs/bots.md); every other
        // bot, the planner included, keeps 20,000 a stroke.
        long sized = Math.round(BotCatalog.TIME_LIMIT_PER_STROKE * BotCatalog.FULL_SEARCH_SIMULATIONS_PER_SECOND);
        assertEquals(sized, BotCatalog.FULL_SEARCH_BUDGET_PER_STROKE);
        assertEquals(BotCatalog.FULL_SEARCH_BUDGET_PER_STROKE, BotCatalog.budgetPerStroke("planner-aces"));
        for (String name : List.of("planner", "robust", "graph", "astar", "hard")) assertEquals(20_000, BotCatalog.budgetPerStroke(name));
    }

    /** What the game's seat gives the bot: a simulator counting against that budget, and the stroke's time limit. */
    @Test
    void aSeatsBotSimulatesWithinItsBudgetAndTheStrokesTime() throws Exception {
        World world = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json"));
        for (String name : List.of("planner-aces", "medium")) {
            long[] budget = {-1};
            double[] seconds = {-1};
            ShotPlanner seat = BotCatalog.fromBot(new minigolf.bot.Bot() {
                public String name() {
                    return name;
                }

                public minigolf.bot.Shot nextShot(minigolf.bot.BotRequest request) {
                    budget[0] = request.simulator().budget();
                    seconds[0] = request.simulator().token().timeLimitSeconds();
                    return minigolf.bot.Shot.of(1, 0);
                }
            });
            double[] shot = seat.plan(world, SimulationSettings.DEFAULT, world.course().start().x(), world.course().start().y(), 0, 1,
                    new BotControl());
            assertEquals(1, shot[0], 1e-12);
            assertEquals(BotCatalog.budgetPerStroke(name), budget[0], name);
            assertEquals(BotCatalog.TIME_LIMIT_PER_STROKE, seconds[0], 1e-9, name);
        }
    }
}
