package minigolf.bot.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.Bot;
import minigolf.bot.BotCancelledException;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.play.Bots;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The noise-aware bot against the planner under velocity noise, and the bot contract under noise. */
class RobustBotTest {
    private static final NoiseModel NOISE = new NoiseModel(0, 0.05);

    private static Playthrough.Result play(String bot, World world, long budget, long seed, CancellationToken token) {
        return Playthrough.play(Bots.create(bot), world, SimulationSettings.DEFAULT, 10, budget, seed, token,
                BotProgress.NONE, new PlayConditions(NOISE, false));
    }

    /** Over 10 seeds at 0.05 m/s on a bench course, robust takes at least {@code gain} strokes fewer than the planner. */
    private static void assertRobustGains(String course, double gain) {
        World world = ShotNoiseTest.load(course);
        double planner = meanStrokes("planner", world, 10), robust = meanStrokes("robust", world, 10);
        System.out.printf("%s, velocity noise 0.05 m/s, 10 seeds: planner %.2f, robust %.2f mean strokes%n",
                course, planner, robust);
        assertTrue(robust <= planner - gain, "planner " + planner + ", robust " + robust);
    }

    private static double meanStrokes(String bot, World world, int seeds) {
        double total = 0;
        for (int seed = 1; seed <= seeds; seed++) {
            Playthrough.Result r = play(bot, world, 20_000, seed, CancellationToken.none());
            assertTrue(r.holed(), bot + " seed " + seed + " not holed in 10 strokes");
            assertTrue(r.botErrors().isEmpty(), r.botErrors().toString());
            total += r.strokes();
        }
        return total / seeds;
    }

    /**
     * Lake-bowl (water on the direct line) at 0.05 m/s, 10 seeds: the planner's ace attempts
     * skirt the water; the robust bot's are scored under the noise. Measured: planner 3.2,
     * robust 2.0 mean strokes.
     */
    @Test
    void onTheLakeTheRobustBotTakesFewerStrokesThanThePlanner() {
        assertRobustGains("lake-bowl", 0.5);
    }

    /** Tree field: measured planner 3.6, robust 2.9; the robust bot must not be worse. */
    @Test
    void onTheTreeFieldTheRobustBotIsNoWorse() {
        assertRobustGains("tree-field", 0);
    }

    /**
     * Sine-cross-limit: the ace needs 4.9-5.4 m/s and a fast miss runs out of bounds; the robust
     * bot lays up along the line when that is cheaper. Measured: planner 4.2, robust 2.0.
     */
    @Test
    void nearTheSpeedLimitTheRobustBotLaysUpAndGainsStrokes() {
        assertRobustGains("sine-cross-limit", 1);
    }

    /**
     * Maze B with hills and pools: the planner's lay-ups beside a pool drown under the noise; the
     * robust bot re-chooses a lay-up that is lost a quarter of the time or more. Measured: planner
     * 5.0, robust 3.9.
     */
    @Test
    void aLayUpThatOftenDrownsIsReplaced() {
        assertRobustGains("maze-b-hills", 0.5);
    }

    /**
     * From the start of sine-cross-limit the planner's ace (about 5 m/s) runs out of bounds past
     * the hole on more than half of the draws; the robust bot plays a softer shot that stays in
     * play (noiseless), and the same request gives the same shot.
     */
    @Test
    void itTradesAnAceThatRunsOutForASaferShotAndIsDeterministic() {
        World slope = ShotNoiseTest.load("sine-cross-limit");
        double x = slope.course().start().x(), y = slope.course().start().y();
        Shot planner = Bots.create("planner").nextShot(new BotRequest(new CountingSimulator(slope), x, y, 0, 9, NOISE));
        Shot robust = Bots.create("robust").nextShot(new BotRequest(new CountingSimulator(slope), x, y, 0, 9, NOISE));
        Shot again = Bots.create("robust").nextShot(new BotRequest(new CountingSimulator(slope), x, y, 0, 9, NOISE));
        assertEquals(robust, again);
        assertTrue(robust.speed() < planner.speed() - 0.2, "planner " + planner.speed() + ", robust " + robust.speed());
        assertFalse(new CountingSimulator(slope).simulate(x, y, robust).outcome().isPenalty());
    }

    @Test
    void underNoiseItKeepsTheBudgetAndAnswersInTime() {
        World lake = ShotNoiseTest.load("lake-bowl");
        for (long budget : new long[]{1, 30, 300}) {
            Playthrough.Result r = play("robust", lake, budget, 3, CancellationToken.none());
            assertTrue(r.simulations() <= budget, "used " + r.simulations() + " of " + budget);
            assertTrue(r.shots().size() >= 1);
            assertTrue(r.botErrors().isEmpty(), r.botErrors().toString());
        }
        // A 0.05 s limit on a budget of a million: it answers, cut by the time limit, long before the
        // budget. Bounded in this thread's CPU time (a wall-clock bound would measure the machine's load).
        long cpu = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
        Playthrough.Result late = play("robust", lake, 1_000_000, 3, CancellationToken.withTimeLimit(0.05));
        double cpuSeconds = (java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime() - cpu) / 1e9;
        assertTrue(late.shots().size() >= 1);
        assertTrue(late.holed() || late.timedOut(), "holed, or the game stopped at the time limit");
        assertTrue(cpuSeconds < 5, "the time limit is kept: " + cpuSeconds + " s of CPU");
    }

    @Test
    void aCancelledRequestThrows() {
        World lake = ShotNoiseTest.load("lake-bowl");
        CancellationToken token = CancellationToken.withTimeLimit(60);
        token.cancel();
        CountingSimulator sim = new CountingSimulator(lake, SimulationSettings.DEFAULT, 10_000, token, BotProgress.NONE);
        Bot bot = Bots.create("robust");
        assertThrows(BotCancelledException.class, () -> bot.nextShot(new BotRequest(sim, -3, 0, 0, 1, NOISE)));
    }

    @Test
    void withoutNoiseItPlaysThePlannersShot() {
        World lake = ShotNoiseTest.load("lake-bowl");
        double x = lake.course().start().x(), y = lake.course().start().y();
        Shot planner = Bots.create("planner").nextShot(new BotRequest(new CountingSimulator(lake), x, y, 0, 5));
        Shot robust = Bots.create("robust").nextShot(new BotRequest(new CountingSimulator(lake), x, y, 0, 5));
        assertEquals(planner, robust);
    }
}
