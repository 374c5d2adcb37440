package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import minigolf.bot.BotRobustnessTestCourses;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.search.SpeedGuess;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Each stage of the planner on its own, from the start of a bench course; every shot a stage
 * returns is replayed on the engine (not through the stage) to check what the stage claims.
 */
class StagesTest {
    /** A stroke from (x, y) with fresh maps and plan, counting its simulations (rest-rule courses: no probe world). */
    static Stroke stroke(World world, double x, double y) {
        CountingSimulator sim = new CountingSimulator(world);
        CourseMaps maps = new CourseMaps();
        maps.prepare(world, CancellationToken.none());
        StrokePlan plan = new StrokePlan(world, maps.grid(), CancellationToken.none());
        return new Stroke(new ArrayList<>(), sim, sim, maps, x, y, () -> plan);
    }

    static Stroke atStart(String course) {
        World world = CycleGuardTest.load(course);
        return stroke(world, world.course().start().x(), world.course().start().y());
    }

    private static ShotResult replay(Stroke s, Shot shot) {
        return new Simulator(s.world, SimulationSettings.DEFAULT).simulate(s.px, s.py, shot.vx(), shot.vy());
    }

    @Test
    void strokeGuessesWithTheEnergyEstimateAndRecordsItsRestingProbes() {
        Stroke s = atStart("flat-7m");
        Shot guess = s.guess(0, 7);
        assertEquals(SpeedGuess.speed(s.world, s.px, s.py, 7, s.holeX, s.holeY, 0.04), guess.speed(), 1e-12);
        Eval e = s.evaluate(Shot.of(2, 0), s.holeX, s.holeY);
        assertEquals(Outcome.STOPPED, e.result().outcome());
        assertEquals(e.restX() - s.holeX, e.fx(), 1e-12);
        assertEquals(1, s.restingProbes.size());
        assertEquals(1, s.sim.count());
    }

    @Test
    void strokeAlongThePathOfAnUnreachableHoleAimsAtTheHole() {
        // The hole walled in: no path along the ground. This was the planner's IndexOutOfBoundsException.
        World walled = BotRobustnessTestCourses.walledIn();
        Stroke s = stroke(walled, -3, 0);
        assertTrue(s.path.isEmpty());
        double[] p = s.pointAlongPath(2);
        assertEquals(s.holeX, p[0], 0);
        assertEquals(s.holeY, p[1], 0);
        assertEquals(61, s.sweepAngles().size());
    }

    @Test
    void holeInOneFindsTheStraightPuttWithOneSimulation() {
        Stroke s = atStart("flat-7m");
        Shot shot = new HoleInOne(s).holeInOne();
        assertEquals(Outcome.HOLED, replay(s, shot).outcome());
        assertEquals(1, s.sim.count());
    }

    @Test
    void holeInOneFindsTheBankShotOffTheWall() {
        Stroke s = atStart("water-bank");
        Shot shot = new HoleInOne(s).holeInOne();
        ShotResult r = new Simulator(s.world, SimulationSettings.DEFAULT).simulate(s.px, s.py, shot.vx(), shot.vy(),
                (minigolf.physics.TrajectoryListener) (t, x, y, vx, vy) -> { });
        assertEquals(Outcome.HOLED, r.outcome());
        // About 52 degrees left of the hole line (scanned: 51.6-51.8), off the wall.
        assertEquals(51.7, Math.toDegrees(Math.atan2(shot.vy(), shot.vx())), 0.3);
    }

    @Test
    void holeInOneGivesUpWhereTheHoleIsBeyondReach() {
        // two-putt: 16 m, a maximum-speed roll 8.15 m. The planner does not even call the stage there;
        // called anyway, it finds nothing and says so.
        Stroke s = atStart("two-putt");
        assertTrue(s.pathLength > 1.3 * s.maxRoll());
        assertNull(new HoleInOne(s).holeInOne());
    }

    @Test
    void twoStrokesFindsALayUpFromWhichOnePuttHoles() {
        // hills-water: no hole-in-one is known; two strokes are (a lay-up over a hill, then one putt).
        Stroke s = atStart("hills-water");
        assertNull(new HoleInOne(s).holeInOne());
        TwoStrokes two = new TwoStrokes(s);
        Shot layup = two.twoStrokes();
        if (layup == null) layup = two.layupSweep();
        assertNotNull(layup);
        ShotResult first = replay(s, layup);
        assertEquals(Outcome.STOPPED, first.outcome());
        // The look-ahead's putt from the rest point, replayed on the engine, holes.
        Solved putt = s.solved.get(s.solved.size() - 1);
        assertEquals(first.endX(), putt.x(), 0);
        assertEquals(first.endY(), putt.y(), 0);
        ShotResult second = new Simulator(s.world, SimulationSettings.DEFAULT).simulate(putt.x(), putt.y(),
                putt.shot().vx(), putt.shot().vy());
        assertEquals(Outcome.HOLED, second.outcome());
    }

    @Test
    void aLayUpInTheMazeRestsNearerTheHoleAlongTheWay() {
        Stroke s = atStart("maze-a");
        Shot shot = new Layup(s).layup(s.maxRoll(), null);
        ShotResult r = replay(s, shot);
        assertEquals(Outcome.STOPPED, r.outcome());
        double before = s.field.at(s.px, s.py), after = s.field.at(r.endX(), r.endY());
        assertTrue(after < before - 3, "from " + before + " m to " + after + " m along the way");
        assertTrue(s.grid.hazardClearance(r.endX(), r.endY()) >= StrokePlan.REST_CLEARANCE);
    }

    @Test
    void theProgressSweepKeepsTheRestPointNearestTheHole() {
        Stroke s = atStart("maze-b");
        s.sim.beginShot(s.px, s.py, r -> r.outcome().isPenalty() ? 1e9 : s.field.at(r.endX(), r.endY()));
        Shot best = new Layup(s).progressSweep();
        double bestDistance = s.field.at(replay(s, best).endX(), replay(s, best).endY());
        for (Eval e : s.restingProbes) {
            assertTrue(s.field.at(e.restX(), e.restY()) >= bestDistance - 1e-9);
        }
        assertEquals(3 * s.sweepAngles().size(), s.sim.count(), "three speeds in every direction");
    }
}
