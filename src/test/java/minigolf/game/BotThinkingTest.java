package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.course.CourseException;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** What the game shows while a bot thinks (progress, its plan) and that Cancel stops it. */
class BotThinkingTest {
    /**
     * No shot holes here (the hole walled in), and on slippery ground (mu_k 0.02) every shot rolls
     * for seconds of simulated time: every bot thinks for seconds, so Cancel always finds it busy.
     */
    static final World WALLED = minigolf.bot.BotRobustnessTestCourses.walledInSlippery();

    static World parse(String json) {
        try {
            return World.parse(json, "test");
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    static World bench(String name) throws CourseException {
        return World.load(Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench/" + name + ".json"));
    }

    @Test
    void everyBotShowsProgressAndStopsOnCancel() throws Exception {
        List<String> answeredFirst = new ArrayList<>();
        int caught = 0;
        for (String name : BotCatalog.names()) {
            if (name.equals("straight")) continue; // answers at once: nothing to cancel
            BotTurn turn = new BotTurn(BotCatalog.planner(name), WALLED, SimulationSettings.DEFAULT, -3, 0, 0, 1L);
            long until = System.nanoTime() + 3_000_000_000L;
            while (turn.progress() == 0 && !turn.isDone() && System.nanoTime() < until) Thread.sleep(5);
            if (turn.isDone()) {
                // Gave up on its own before it could be cancelled (newton does on this course): nothing to time.
                answeredFirst.add(name);
                continue;
            }
            caught++;
            assertTrue(turn.progress() > 0, name + " shows progress: " + turn.message());
            turn.cancel();
            // The thread ends and says so (within seconds however loaded the machine; that no
            // simulation starts after a cancel is CountingSimulatorTest's, without a clock).
            turn.join(30_000);
            assertTrue(turn.isDone(), name + " ended after Cancel");
            assertEquals("cancelled", turn.failure(), name);
        }
        // At most two may give up on their own before the first progress report (newton always
        // does here; astar does when it finds no path quickly on a loaded machine).
        assertTrue(caught >= BotCatalog.names().size() - 3, "caught thinking: " + caught + "; answered first: " + answeredFirst);
        assertTrue(answeredFirst.stream().noneMatch(n -> n.startsWith("planner") || n.equals("robust") || n.equals("graph")),
                "the searching bots are caught thinking: " + answeredFirst);
    }

    @Test
    void thePlannerAndTheAStarBotsShowTheRouteTheyIntend() throws Exception {
        World maze = bench("maze-a");
        double bx = maze.course().start().x(), by = maze.course().start().y();
        double hx = maze.hole().position().x(), hy = maze.hole().position().y();
        for (String name : List.of("planner", "astar", "astar-newton")) {
            BotTurn turn = new BotTurn(BotCatalog.planner(name), maze, SimulationSettings.DEFAULT, bx, by, 0, 1L);
            turn.join(30_000);
            List<double[]> plan = turn.plan();
            assertTrue(plan.size() >= 3, name + ": a route round the maze's walls, got " + plan.size() + " points");
            assertEquals(bx, plan.get(0)[0], 1e-9, name + " starts at the ball");
            assertEquals(by, plan.get(0)[1], 1e-9, name);
            assertEquals(hx, plan.get(plan.size() - 1)[0], 1e-9, name + " ends at the hole");
            assertEquals(hy, plan.get(plan.size() - 1)[1], 1e-9, name);
            double length = 0;
            for (int i = 1; i < plan.size(); i++) {
                length += Math.hypot(plan.get(i)[0] - plan.get(i - 1)[0], plan.get(i)[1] - plan.get(i - 1)[1]);
            }
            assertTrue(length > 1.2 * Math.hypot(hx - bx, hy - by), name + ": round the walls, not through them: " + length);
        }
    }

    @Test
    void oneBotPerPlayerPerHoleSoItsMemoryLastsTheHole() throws Exception {
        BotSeats seats = new BotSeats();
        World hole1 = bench("flat-7m"), hole2 = bench("maze-a");
        ShotPlanner first = seats.planner(0, "planner", hole1);
        assertSame(first, seats.planner(0, "planner", hole1), "the same bot for the next stroke");
        assertNotSame(first, seats.planner(1, "planner", hole1), "another player, another bot");
        assertNotSame(first, seats.planner(0, "planner", hole2), "a new hole starts afresh");
        ShotPlanner again = seats.planner(0, "planner", hole2);
        seats.clear();
        assertNotSame(again, seats.planner(0, "planner", hole2), "after a cancel, never the old bot");
        assertEquals(null, seats.planner(0, "no such bot", hole2));
    }
}
