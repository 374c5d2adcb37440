package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The robustness property of {@link BotRobustnessTest} extended to the elements of issue 24: on
 * courses the loader accepts with any combination of moving obstacles, bumpers, one-way gates, push
 * zones, magnets and teleports, no bot throws, hangs, overspends or plays an illegal shot, and a
 * shot's wait is a legal one (0 or more, within the course's longest period).
 */
class ElementsRobustnessTest {
    /** Every bot on courses with a random mix of elements. */
    static List<Arguments> botsOnElementCourses() {
        List<World> worlds = RandomElements.mixed(2424L, 6);
        List<Arguments> all = new ArrayList<>();
        for (int i = 0; i < worlds.size(); i++) {
            for (String bot : Bots.names()) all.add(Arguments.of(bot, i, worlds.get(i)));
        }
        return all;
    }

    @ParameterizedTest(name = "{0} on element course {1}")
    @MethodSource("botsOnElementCourses")
    void noBotCrashesOrHangsAmongTheElements(String bot, int index, World world) {
        checkWaits(world, BotRobustnessTest.playChecked(bot, world, 200, 2));
    }

    /** The planner on one course for each of the 63 combinations of the six kinds. */
    static List<Arguments> everyCombination() {
        List<Arguments> all = new ArrayList<>();
        for (int mask = 1; mask < 1 << RandomElements.KINDS.length; mask++) {
            List<String> kinds = new ArrayList<>();
            for (int k = 0; k < RandomElements.KINDS.length; k++) if ((mask & 1 << k) != 0) kinds.add(RandomElements.KINDS[k]);
            all.add(Arguments.of(String.join("+", kinds), RandomElements.course(24_000L + mask, mask)));
        }
        return all;
    }

    @ParameterizedTest(name = "planner with {0}")
    @MethodSource("everyCombination")
    void thePlannerAnswersOnEveryCombinationOfElements(String kinds, World world) {
        checkWaits(world, BotRobustnessTest.playChecked("planner", world, 300, 2));
    }

    @Test
    void theCombinationsReallyHoldTheirElements() {
        World all = RandomElements.course(24_063L, 63);
        assertTrue(all.moving() != null && all.gates() != null && all.forces() != null && all.teleports() != null,
                "every kind on the course with all of them");
        assertTrue(all.course().obstacles().stream().anyMatch(o -> o instanceof minigolf.course.Obstacle.Bumper));
        assertTrue(!all.course().pushZones().isEmpty() && !all.course().magnets().isEmpty());
    }

    private static void checkWaits(World world, Playthrough.Result r) {
        double period = 0;
        for (var o : world.course().obstacles()) {
            if (o instanceof minigolf.course.Obstacle.Moving m) period = Math.max(period, m.motion().period());
        }
        for (Playthrough.PlayedShot s : r.shots()) {
            double wait = s.intended().waitSeconds();
            assertTrue(wait >= 0 && (wait == 0 || wait < period), world.course().name() + ": wait " + wait + " of period " + period);
        }
    }
}
