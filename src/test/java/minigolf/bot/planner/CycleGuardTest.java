package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.Shot;
import minigolf.bot.play.Playthrough;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The planner's cycle memory: no stroke leads back to a position played from. */
class CycleGuardTest {
    private static final World FLAT = load("flat-7m"), POND = load("pond");

    static World load(String name) {
        try {
            return World.load(Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench/" + name + ".json"));
        } catch (minigolf.course.CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    private static ShotResult rest(Outcome outcome, double x, double y) {
        return new ShotResult(outcome, x, y, 1, 60, 0, List.of());
    }

    @Test
    void aStrokeLeadsBackWhenItEndsNearAPositionPlayedFromOrIsLost() {
        CycleGuard guard = new CycleGuard();
        guard.visit(FLAT, 0, 0, 0);
        guard.visit(FLAT, 2, 0, 1);
        assertTrue(guard.leadsBack(rest(Outcome.STOPPED, 0.05, 0.05)), "back at the first position (7 cm off)");
        assertTrue(guard.leadsBack(rest(Outcome.STOPPED, 2.0, 0.09)), "no progress from the ball (9 cm)");
        assertFalse(guard.leadsBack(rest(Outcome.STOPPED, 1.0, 0.0)), "a new place");
        assertFalse(guard.leadsBack(rest(Outcome.STOPPED, 2.0, 0.11)), "11 cm from the ball is a new place");
        assertTrue(guard.leadsBack(rest(Outcome.WATER, 5, 5)), "lost: the ball goes back where it was");
        assertTrue(guard.leadsBack(rest(Outcome.OUT, 5, 5)));
        assertFalse(guard.leadsBack(rest(Outcome.HOLED, 0, 0)), "holed ends the game, wherever the hole is");
    }

    @Test
    void aNewGameOrCourseForgetsThePositions() {
        CycleGuard guard = new CycleGuard();
        guard.visit(FLAT, 0, 0, 0);
        guard.visit(FLAT, 1, 0, 1);
        assertEquals(2, guard.visited().size());
        guard.visit(FLAT, 1, 0, 2);
        assertEquals(2, guard.visited().size(), "the same place is remembered once");
        guard.visit(FLAT, 3, 0, 0);
        assertEquals(1, guard.visited().size(), "strokesTaken 0: a new game");
        guard.visit(POND, 3, 0, 4);
        assertEquals(1, guard.visited().size(), "another course");
        assertFalse(guard.leadsBack(rest(Outcome.STOPPED, 0, 0)));
    }

    @Test
    void aChoiceThatLeadsBackIsReplacedByTheBestKnownShotThatDoesNot() {
        CycleGuard guard = new CycleGuard();
        guard.visit(FLAT, 0, 0, 0);
        guard.visit(FLAT, 4, 0, 1);
        Shot back = Shot.of(-2, 0), lost = Shot.of(9, 9), near = Shot.of(1, 0), far = Shot.of(0, 1);
        Map<Shot, ShotResult> known = new LinkedHashMap<>();
        known.put(back, rest(Outcome.STOPPED, 0.02, 0));
        known.put(lost, rest(Outcome.WATER, 6, 6));
        known.put(near, rest(Outcome.STOPPED, 5, 0));
        known.put(far, rest(Outcome.STOPPED, 4, 3));
        // Score: distance to a hole at (6, 0); the shot back to the start would score best (it does not count).
        minigolf.bot.CountingSimulator.ShotScore score = r -> r.outcome().isPenalty() ? 1e9 : Math.hypot(r.endX() - 6, r.endY());
        assertSame(near, guard.choose(back, known.get(back), known, score));
        assertSame(near, guard.choose(near, known.get(near), known, score), "a choice that makes progress stands");
        assertSame(far, guard.choose(far, known.get(far), known, score), "even when another scores better");
        known.remove(near);
        known.remove(far);
        assertNull(guard.choose(back, known.get(back), known, score), "nothing known makes progress");
    }

    @Test
    void thePlannerNeverPlaysBackToAPlaceItPlayedFromOnAWalledInHole() {
        // The hole stands inside a closed box of walls too high to chip over: no shot holes, every stroke
        // is a lay-up. Without the cycle memory the planner's second stroke (against the box) leaves the
        // ball where it was. (Over the 0.5 m box of walledIn() the planner now lobs.)
        World walled = minigolf.bot.BotRobustnessTestCourses.walledInHigh();
        Playthrough.Result r = Playthrough.play(new PlannerBot(), walled, SimulationSettings.DEFAULT, 8, 20_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertFalse(r.holed());
        double x = walled.course().start().x(), y = walled.course().start().y();
        List<double[]> from = new java.util.ArrayList<>();
        for (Playthrough.PlayedShot s : r.shots()) {
            from.add(new double[] {x, y});
            assertEquals(Outcome.STOPPED, s.result().outcome());
            for (double[] p : from) {
                assertTrue(Math.hypot(s.result().endX() - p[0], s.result().endY() - p[1]) >= CycleGuard.RADIUS,
                        "stroke " + from.size() + " ends at (" + s.result().endX() + ", " + s.result().endY()
                                + "), where the ball was played from before");
            }
            x = s.result().endX();
            y = s.result().endY();
        }
    }
}
