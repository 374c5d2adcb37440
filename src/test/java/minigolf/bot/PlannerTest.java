package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Playthrough;
import minigolf.bot.search.SearchBot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The planner on every bench course: holed, and in the fewest strokes where we know them. */
class PlannerTest {
    @ParameterizedTest
    @CsvSource({
        // course, most strokes allowed (1 = hole-in-one; two-putt: the hole is beyond a max-speed roll)
        "flat-7m, 1", "flat-20m, 1", "lake-bowl, 1", "pond, 1", "sine-cross-limit, 1",
        "two-putt, 2", "hills-water, 2", "water-slalom, 3"})
    void holesEveryBenchCourse(String course, int maxStrokes) {
        World world = BenchCourses.load(course);
        for (long seed : new long[] {1, 2, 3}) {
            Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000,
                    seed, CancellationToken.none(), BotProgress.NONE);
            assertTrue(r.holed(), course + " not holed: " + r);
            assertTrue(r.strokes() <= maxStrokes, course + ": " + r.strokes() + " strokes");
            assertTrue(r.shots().stream().noneMatch(s -> s.result().outcome().isPenalty()), course + ": a penalty");
        }
    }

    @ParameterizedTest
    @CsvSource({
        // course, most strokes allowed: what the planner takes (measured, docs/bots.md)
        "maze-a, 5", "maze-b, 3", "maze-b-hills, 3", "maze-c, 1", "maze-c-hills, 2", "maze-d, 4", "maze-e, 3",
        "tree-field, 1", "water-bank, 1"})
    void holesEveryMazeAndObstacleCourse(String course, int maxStrokes) {
        World world = BenchCourses.load(course);
        assertTrue(!world.course().obstacles().isEmpty(), course + " has obstacles");
        for (long seed : new long[] {1, 7}) {
            Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000,
                    seed, CancellationToken.none(), BotProgress.NONE);
            assertTrue(r.holed(), course + " not holed: " + r);
            assertTrue(r.strokes() <= maxStrokes, course + ": " + r.strokes() + " strokes");
            assertTrue(r.shots().stream().noneMatch(s -> s.result().outcome().isPenalty()), course + ": a penalty");
        }
    }

    @org.junit.jupiter.api.Test
    void banksRoundTheBigObstacleOfMazeCInOneStroke() {
        // The box stands across the straight line from the start to the hole: the ball must go round it.
        World world = BenchCourses.load("maze-c");
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double v = world.physics().maxSpeed();
        assertTrue(engine.simulate(-4, 0, 0.7 * v, 0).endX() < -0.75, "the straight putt stops at the box");
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertEquals(1, r.strokes());
        assertEquals(Outcome.HOLED, r.shots().get(0).result().outcome());
    }

    @org.junit.jupiter.api.Test
    void findsTheTreeFieldsHoleInOneOffATrunk() {
        // The hole-in-one caroms off a trunk: the shots 0.1 deg either side of its corridor miss by
        // metres, and the 4-degree sweep's nearest shot (hole direction + 8 deg) comes to rest
        // well away from the hole, so only the fine sweep around promising shots sees it.
        World world = BenchCourses.load("tree-field");
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        double sx = world.course().start().x(), sy = world.course().start().y();
        double holeAngle = Math.atan2(hy - sy, hx - sx);
        for (double speed : new double[] {4.3, 4.4, 4.5}) {
            ShotResult r = engine.simulate(sx, sy, speed * Math.cos(holeAngle + Math.toRadians(8)),
                    speed * Math.sin(holeAngle + Math.toRadians(8)));
            assertTrue(Math.hypot(r.endX() - hx, r.endY() - hy) > 1, "the coarse sweep's shot nearly holes: " + r);
        }
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertEquals(1, r.strokes());
        assertEquals(Outcome.HOLED, r.shots().get(0).result().outcome());
        assertTrue(r.shots().get(0).simulations() <= 1000, "simulations: " + r.shots().get(0).simulations());
    }

    @org.junit.jupiter.api.Test
    void findsTheWaterBankHoleInOneOffTheWall() {
        // The pond lies across the direct line: the straight putt at the physics speed drowns.
        World world = BenchCourses.load("water-bank");
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double sx = world.course().start().x(), sy = world.course().start().y();
        Shot straight = SearchBot.directGuess(world, sx, sy);
        assertEquals(Outcome.WATER, engine.simulate(sx, sy, straight.vx(), straight.vy()).outcome());
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertEquals(1, r.strokes());
        assertEquals(Outcome.HOLED, r.shots().get(0).result().outcome());
        assertTrue(r.shots().get(0).simulations() <= 60, "simulations: " + r.shots().get(0).simulations());
        // ... and it is a bank shot: the ball hits the wall along the top edge (y = 2.5) first.
        Shot shot = r.shots().get(0).shot();
        java.util.List<minigolf.physics.StrokeEvent> hits = new java.util.ArrayList<>();
        engine.simulate(sx, sy, shot.vx(), shot.vy(), new minigolf.physics.TrajectoryListener() {
            @Override
            public void onStep(double t, double x, double y, double vx, double vy) {
            }

            @Override
            public void onEvent(minigolf.physics.StrokeEvent event) {
                if (event.type() == minigolf.physics.StrokeEvent.Type.COLLISION) hits.add(event);
            }
        });
        assertEquals(1, hits.size(), "one bounce: " + hits);
        assertTrue(hits.get(0).y() > 2.3, "the bounce is at the wall: " + hits.get(0));
    }

    @org.junit.jupiter.api.Test
    void holesHillsWaterInTwoStrokesWithACurvedLayup() {
        // No hole-in-one is known here; the plan's straight lay-ups need 3 strokes. The lay-up
        // sweep finds a rest point (far off the hole's line) from which one putt holes.
        World world = BenchCourses.load("hills-water");
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed(), r.toString());
        assertEquals(2, r.strokes());
        assertTrue(r.shots().stream().noneMatch(s -> s.result().outcome().isPenalty()), "a penalty");
        double sx = world.course().start().x(), sy = world.course().start().y();
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        Shot first = r.shots().get(0).shot();
        double off = Math.abs(Math.IEEEremainder(Math.atan2(first.vy(), first.vx()) - Math.atan2(hy - sy, hx - sx), 2 * Math.PI));
        assertTrue(Math.toDegrees(off) > 30, "the lay-up goes round the pools: " + Math.toDegrees(off) + " deg off");
        assertTrue(r.simulations() <= 400, "simulations: " + r.simulations());
    }

    @ParameterizedTest
    @CsvSource({
        // course, most simulations for the whole game (measured: 6, 33, 154; issue 5's targets 8 and 60)
        "lake-bowl, 8", "water-slalom, 60", "hills-water, 160"})
    void holesWaterCoursesWithFewSimulations(String course, int maxSimulations) {
        // lake-bowl: Broyden from the sweep's first shot round the lake, aiming at the near side of
        // the hole once a step towards the centre drowns; water-slalom: a sweep all of whose first
        // 24 shots are lost gives up; the look-ahead's holing shot is reused on the next stroke.
        World world = BenchCourses.load(course);
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed(), r.toString());
        assertTrue(r.simulations() <= maxSimulations, course + ": " + r.simulations() + " simulations");
        if (course.equals("water-slalom")) assertEquals(3, r.strokes());
        if (course.equals("lake-bowl")) assertEquals(1, r.strokes());
    }

    @org.junit.jupiter.api.Test
    void twoPuttNeedsTwoStrokesAndTakesTwo() {
        World world = BenchCourses.load("two-putt");
        double v = world.physics().maxSpeed(), mu = world.physics().kineticFriction();
        double maxRoll = v * v / (2 * mu * world.physics().gravity());
        double distance = world.course().start().distanceTo(world.hole().position());
        assertTrue(maxRoll < distance, "no hole-in-one: " + maxRoll + " m < " + distance + " m");
        Playthrough.Result r = Playthrough.play(new PlannerBot(), world, SimulationSettings.DEFAULT, 10, 100_000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertEquals(2, r.strokes());
    }

    @org.junit.jupiter.api.Test
    void aimsAtTheCentreOfTheHoleNotItsEdge() {
        // Rest rule: the planner's hole-in-one on flat ground rests within 3 cm of the centre.
        World world = BenchCourses.load("flat-7m");
        CountingSimulator sim = new CountingSimulator(world);
        Shot shot = new PlannerBot().nextShot(new BotRequest(sim, -3.5, 0, 0, 1));
        ShotResult r = new Simulator(world, SimulationSettings.DEFAULT).simulate(-3.5, 0, shot.vx(), shot.vy());
        assertEquals(Outcome.HOLED, r.outcome());
        assertTrue(Math.hypot(r.endX() - 3.5, r.endY()) < 0.03, "rest point " + r.endX() + ", " + r.endY());
    }
}
