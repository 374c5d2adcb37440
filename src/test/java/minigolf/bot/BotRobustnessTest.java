package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.bot.search.SearchBot;
import minigolf.course.CourseException;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every bot always answers: on courses where the hole cannot be reached at all (walled in, ringed
 * by water, a maximum speed that barely moves the ball, friction that stops it at once), with no
 * friction, with a ball too big for the gaps, and on random courses the loader accepts. No
 * exception, no error recovered from, the budget kept, a legal shot every stroke.
 */
class BotRobustnessTest {
    private static final String FLAT = "{\"format\":1,\"name\":\"%s\",\"terrain\":{\"height\":\"%s\"},"
            + "\"bounds\":{\"min\":[-5,-3],\"max\":[5,3]},\"physics\":{\"kineticFriction\":%s,\"staticFriction\":%s,"
            + "\"maxSpeed\":%s,\"ballRadius\":%s},\"start\":[-3,0],\"hole\":{\"position\":[3,0],\"radius\":0.1,\"rule\":\"rest\"},"
            + "\"obstacles\":[%s]}";
    static final String BOX_ROUND_HOLE = "{\"type\":\"wall\",\"from\":[2,-1],\"to\":[4,-1],\"thickness\":0.1,\"height\":0.5},"
            + "{\"type\":\"wall\",\"from\":[4,-1],\"to\":[4,1],\"thickness\":0.1,\"height\":0.5},"
            + "{\"type\":\"wall\",\"from\":[4,1],\"to\":[2,1],\"thickness\":0.1,\"height\":0.5},"
            + "{\"type\":\"wall\",\"from\":[2,1],\"to\":[2,-1],\"thickness\":0.1,\"height\":0.5}";

    static World course(String name, String height, double muK, double muS, double maxSpeed, double ballRadius,
                        String obstacles) {
        try {
            return World.parse(String.format(java.util.Locale.ROOT, FLAT, name, height, muK, muS, maxSpeed, ballRadius,
                    obstacles), name);
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** Courses no shot can hole, and whether that is so. */
    static List<Arguments> hardCourses() {
        List<Arguments> courses = new ArrayList<>();
        courses.add(Arguments.of("walled in", course("walled in", "0", 0.1, 0.2, 5, 0.02135, BOX_ROUND_HOLE), true));
        courses.add(Arguments.of("ringed by water", course("ringed by water",
                "0.2-0.5*exp(-((sqrt((x-3)^2+y^2)-1.5)^2)/0.2)", 0.1, 0.2, 5, 0.02135, ""), true));
        courses.add(Arguments.of("tiny maximum speed", course("tiny maximum speed", "0", 0.1, 0.2, 0.001, 0.02135, ""), true));
        courses.add(Arguments.of("huge friction", course("huge friction", "0", 50, 60, 5, 0.02135, ""), true));
        courses.add(Arguments.of("no friction", course("no friction", "0", 0, 0, 5, 0.02135, ""), true));
        courses.add(Arguments.of("ball too big for the gap", course("ball too big for the gap", "0", 0.1, 0.2, 5, 0.5,
                "{\"type\":\"wall\",\"from\":[0,-2.4],\"to\":[0,2.4],\"thickness\":0.1,\"height\":2}"), true));
        return courses;
    }

    static List<Arguments> botsOnHardCourses() {
        List<Arguments> all = new ArrayList<>();
        for (Arguments c : hardCourses()) {
            for (String bot : Bots.names()) all.add(Arguments.of(bot, c.get()[0], c.get()[1], c.get()[2]));
        }
        return all;
    }

    /**
     * The settings of these games: the game's, but a stroke ends after 30 s of simulated time (600 s
     * in the game), because on some random courses the engine keeps a ball hopping until that limit,
     * and 600 s of hopping takes the engine over a second to compute.
     */
    static final SimulationSettings SETTINGS = new SimulationSettings(SimulationSettings.DEFAULT.integrator(),
            SimulationSettings.DEFAULT_DT, 30);

    /**
     * Plays a short game with a time limit (what every bot must keep) and a hang guard far above
     * it (a bot that ignores its token would trip it); checks what every game must satisfy.
     */
    static Playthrough.Result playChecked(String bot, World world, long budget, int maxStrokes) {
        CancellationToken token = CancellationToken.withTimeLimit(5);
        java.util.concurrent.ExecutorService thread = java.util.concurrent.Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "bot " + bot);
            t.setDaemon(true);
            return t;
        });
        Playthrough.Result r;
        try {
            r = thread.submit(() -> Playthrough.play(Bots.create(bot), world, SETTINGS, maxStrokes, budget, 7, token,
                    BotProgress.NONE)).get(120, java.util.concurrent.TimeUnit.SECONDS);
        } catch (java.util.concurrent.TimeoutException e) {
            token.cancel();
            throw new AssertionError(bot + " hangs on " + world.course().name() + " (no answer in 120 s with a 5 s limit)");
        } catch (InterruptedException | java.util.concurrent.ExecutionException e) {
            throw new AssertionError(bot + " on " + world.course().name() + ": " + e.getCause(), e.getCause());
        } finally {
            thread.shutdown();
        }
        String where = bot + " on " + world.course().name() + ": ";
        assertEquals(List.of(), r.botErrors(), where + "errors");
        assertTrue(r.simulations() <= budget, where + r.simulations() + " simulations of " + budget);
        assertTrue(r.shots().size() >= 1, where + "no shot");
        for (Playthrough.PlayedShot s : r.shots()) {
            assertTrue(s.shot().speed() <= world.physics().maxSpeed(), where + "shot faster than allowed: " + s.shot());
        }
        return r;
    }

    @ParameterizedTest(name = "{0} on {1}")
    @MethodSource("botsOnHardCourses")
    void everyBotAnswersWhereNoShotHoles(String bot, String name, World world, boolean impossible) {
        Playthrough.Result r = playChecked(bot, world, 400, 3);
        if (impossible) assertFalse(r.holed(), bot + " holed " + name + ", which cannot be holed");
    }

    @Test
    void theHardCoursesReallyCannotBeHoled() {
        // Independent of every bot: a fan of shots from the start never holes, never stops in the hole.
        for (Arguments a : hardCourses()) {
            World world = (World) a.get()[1];
            minigolf.physics.Simulator engine = new minigolf.physics.Simulator(world, SETTINGS);
            for (int d = 0; d < 72; d++) {
                for (double f : new double[] {0.2, 0.5, 0.8, 1.0}) {
                    double v = f * world.physics().maxSpeed() * (1 - 1e-12), angle = Math.toRadians(5 * d);
                    Outcome o = engine.simulate(-3, 0, v * Math.cos(angle), v * Math.sin(angle)).outcome();
                    assertTrue(o != Outcome.HOLED, a.get()[0] + ": a shot holes at " + 5 * d + " deg, " + v + " m/s");
                }
            }
        }
    }

    static List<Arguments> botsOnRandomCourses() {
        List<World> worlds = RandomCourses.generate(20261124L, 16);
        List<Arguments> all = new ArrayList<>();
        for (int i = 0; i < worlds.size(); i++) {
            for (String bot : Bots.names()) all.add(Arguments.of(bot, i, worlds.get(i)));
        }
        return all;
    }

    /** The property: on any course the loader accepts, no bot throws, hangs, overspends or plays an illegal shot. */
    @ParameterizedTest(name = "{0} on random course {1}")
    @MethodSource("botsOnRandomCourses")
    void noBotCrashesOrHangsOnRandomCourses(String bot, int index, World world) {
        playChecked(bot, world, 200, 2);
    }

    static List<Arguments> hardAndRandomCourses() {
        List<Arguments> all = new ArrayList<>();
        for (Arguments c : hardCourses()) all.add(Arguments.of(c.get()[0], c.get()[1]));
        List<World> worlds = RandomCourses.generate(20261124L, 16);
        for (int i = 0; i < worlds.size(); i++) all.add(Arguments.of("random course " + i, worlds.get(i)));
        return all;
    }

    /**
     * The same property for the planner's full search (a budget of 1,000,000: the dense sweep, the
     * two-stroke search, the three-stroke plan), which the small budgets above never start: it
     * keeps the 5 s limit and answers everywhere.
     */
    @ParameterizedTest(name = "planner's full search on {0}")
    @MethodSource("hardAndRandomCourses")
    void thePlannersFullSearchAnswersEverywhere(String name, World world) {
        playChecked("planner", world, 1_000_000, 2);
    }

    @ParameterizedTest
    @MethodSource("minigolf.bot.AllBotsTest#bots")
    void aTimeLimitThatHasRunOutStillGivesAShot(String bot) {
        // The limit is over before the bot starts: it answers at once with the physics guess (into the
        // pond, which lies on the straight line), and the game stops.
        CancellationToken token = CancellationToken.withTimeLimit(1e-9);
        World world = BenchCourses.load("pond");
        Playthrough.Result r = Playthrough.play(Bots.create(bot), world, SimulationSettings.DEFAULT, 10, 1000, 1, token,
                BotProgress.NONE);
        assertEquals(1, r.shots().size());
        assertEquals(0, r.simulations());
        assertTrue(r.timedOut());
        assertEquals(List.of(), r.botErrors());
        assertEquals(SearchBot.directGuess(world, -4.5, 0).limitedTo(world.physics().maxSpeed() * (1 - 1e-12)),
                r.shots().get(0).shot());
    }
}
