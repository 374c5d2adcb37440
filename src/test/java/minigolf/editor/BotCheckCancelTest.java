package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.CourseException;
import minigolf.game.BotCatalog;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** "Ask a bot" shows the stroke, progress and the bot's route, and Cancel stops it. */
class BotCheckCancelTest {
    @Test
    void cancelStopsThePlannerAndThePlanIsShown() throws Exception {
        // A ring of water round the hole: the planner searches every stroke until stopped.
        World ringed = World.parse("{\"format\":1,\"name\":\"ringed\",\"terrain\":{\"height\":"
                + "\"0.2-0.5*exp(-((sqrt((x-3)^2+y^2)-1.5)^2)/0.2)\"},\"bounds\":{\"min\":[-5,-3],\"max\":[5,3]},"
                + "\"physics\":{\"kineticFriction\":0.1,\"staticFriction\":0.2,\"maxSpeed\":5},\"start\":[-3,0],"
                + "\"hole\":{\"position\":[3,0],\"radius\":0.1,\"rule\":\"rest\"}}", "ringed");
        BotCheck check = BotCheck.start(BotCatalog.planner("planner"), ringed, SimulationSettings.DEFAULT, 12, 1);
        long until = System.nanoTime() + 5_000_000_000L;
        while ((check.plan().isEmpty() || check.progress() == 0) && System.nanoTime() < until) Thread.sleep(5);
        assertFalse(check.isDone());
        assertTrue(check.progress() > 0, check.message());
        assertTrue(check.message().startsWith("stroke 1: "), check.message());
        assertEquals(2, check.plan().size(), "no ground route: straight at the hole");
        check.cancel();
        // Its thread ends and says so (a bound of seconds: the machine may be loaded; that no
        // simulation starts after a cancel is CountingSimulatorTest's, without a clock).
        check.join(30_000);
        assertTrue(check.isDone(), "ended after Cancel");
        assertEquals("cancelled", check.failure());
        double progress = check.progress();
        String message = check.message();
        Thread.sleep(100);
        assertEquals(progress, check.progress(), "nothing moves after the end");
        assertEquals(message, check.message());
    }
}
