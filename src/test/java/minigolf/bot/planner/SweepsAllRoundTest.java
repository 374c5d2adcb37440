package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.course.Course;
import minigolf.course.CourseLoader;
import minigolf.course.HoleRule;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The quick plan's sweep on every stroke is for putts-only courses (the imported classic tracks):
 * a world's hole is a capture hole too, and its bots must keep the plan the levels were calibrated on.
 */
class SweepsAllRoundTest {
    @Test
    void onlyPuttsOnlyCoursesWithACaptureHoleAreSweptOnEveryStroke() throws Exception {
        Course gatehouse = CourseLoader.load(Path.of("courses/worlds/winter/01-gatehouse.json"));
        assertEquals(HoleRule.CAPTURE, gatehouse.hole().rule());
        assertFalse(gatehouse.physics().puttsOnly());
        assertFalse(PlannerBot.sweepsAllRound(World.of(gatehouse)));
        Course putts = gatehouse.withPhysics(gatehouse.physics().withPuttsOnly(true));
        assertTrue(PlannerBot.sweepsAllRound(World.of(putts)));
    }
}
