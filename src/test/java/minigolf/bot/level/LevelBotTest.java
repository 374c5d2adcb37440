package minigolf.bot.level;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.SplittableRandom;
import minigolf.bot.BotProgress;
import minigolf.bot.BotRequest;
import minigolf.bot.CancellationToken;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.noise.HumanError;
import minigolf.bot.noise.RobustBot;
import minigolf.bot.planner.PlannerBot;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The opponents by level: their error model, determinism, and that pro is the planner. */
class LevelBotTest {
    private static final Path BENCH = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench");

    private static BotRequest request(World world, int strokesTaken, long seed) {
        CountingSimulator sim = new CountingSimulator(world, SimulationSettings.DEFAULT, 20_000, new CancellationToken(),
                BotProgress.NONE);
        return new BotRequest(sim, world.course().start().x(), world.course().start().y(), strokesTaken, seed);
    }

    @Test
    void aHumanErrorTurnsTheShotAndScalesItsPaceAsDrawn() {
        HumanError error = new HumanError(Math.toRadians(3), 0.1);
        SplittableRandom draws = new SplittableRandom(7);
        double turn = Math.toRadians(3) * draws.nextGaussian(), scale = 1 + 0.1 * draws.nextGaussian();
        Shot played = error.play(Shot.polar(0.4, 2.0), new SplittableRandom(7), 5);
        assertEquals(0.4 + turn, Math.atan2(played.vy(), played.vx()), 1e-12);
        assertEquals(2.0 * scale, played.speed(), 1e-12);
        assertEquals(0, played.vz());
        // A chip's lift scales with its pace; no draw is faster than the course allows.
        Shot chip = error.play(new Shot(1, 0, 1), new SplittableRandom(7), 5);
        assertEquals(scale, chip.vz(), 1e-12);
        assertTrue(new HumanError(0, 10).play(Shot.of(4, 0), new SplittableRandom(1), 5).speed() < 5);
        // A draw far below -1 leaves a fifth of the pace, never a ball struck backwards.
        assertEquals(0.2 * 3, new HumanError(0, 1e6).play(Shot.of(3, 0), new SplittableRandom(3), 5).speed(), 1e-9);
    }

    @Test
    void noErrorPlaysTheShotAsChosen() {
        Shot shot = Shot.of(1.5, -0.25);
        assertSame(shot, HumanError.NONE.play(shot, new SplittableRandom(1), 5));
    }

    @Test
    void theErrorShrinksWithEveryStrokeOnceCareful() {
        // medium (and hard): halving from the sixth stroke.
        LevelBot medium = new LevelBot(Level.MEDIUM);
        HumanError full = Level.MEDIUM.error();
        for (int s = 0; s < 5; s++) assertEquals(full, medium.errorAfter(s));
        assertEquals(full.angle() / 2, medium.errorAfter(5).angle(), 1e-15);
        assertEquals(full.pace() / 4, medium.errorAfter(6).pace(), 1e-15);
        assertEquals(full.pace() / 32, medium.errorAfter(9).pace(), 1e-15);
        // easy: its own care.
        LevelBot easy = new LevelBot(Level.EASY);
        LevelBot.Care care = Level.EASY.care();
        for (int s = 0; s < care.from(); s++) assertEquals(Level.EASY.error(), easy.errorAfter(s));
        assertEquals(Level.EASY.error().angle() * care.shrink(), easy.errorAfter(care.from()).angle(), 1e-15);
        assertEquals(Level.EASY.error().pace() * Math.pow(care.shrink(), 3), easy.errorAfter(care.from() + 2).pace(), 1e-15);
    }

    /**
     * Once careful, a level that lays up plays the robust bot's shot for its own (full) error, struck
     * with its error; before, the planner's line. On the pond the two differ (the bold line skirts the water).
     */
    @Test
    void aCarefulLevelLaysUpAsTheRobustBotForItsOwnErrorAndNotBefore() throws Exception {
        World pond = World.load(BENCH.resolve("pond.json"));
        HumanError error = new HumanError(Math.toRadians(6), 0.2);
        LevelBot.Care care = new LevelBot.Care(1, 1, true);
        double max = pond.physics().maxSpeed();
        BotRequest first = request(pond, 0, 5), second = request(pond, 1, 5);
        Shot planner = first.simulator().limit(new PlannerBot().nextShot(first));
        BotRequest noisy = new BotRequest(request(pond, 1, 5).simulator(), second.ballX(), second.ballY(), 1, 5,
                error.asNoiseModel(LevelBot.PLANNING_SPEED));
        Shot robust = noisy.simulator().limit(new RobustBot().nextShot(noisy));
        assertNotEquals(planner, robust, "on the pond the robust bot lays up off the planner's line");
        assertEquals(error.play(planner, new SplittableRandom(5 ^ LevelBot.ERROR_SALT), max),
                new LevelBot("careful", error, error, false, care).nextShot(request(pond, 0, 5)), "before: the planner's line");
        assertEquals(error.play(robust, new SplittableRandom(5 ^ LevelBot.ERROR_SALT), max),
                new LevelBot("careful", error, error, false, care).nextShot(request(pond, 1, 5)), "careful: the robust bot's");
    }

    @Test
    void theLevelsErrLessInOrder() {
        Level[] levels = Level.values();
        for (int i = 1; i < levels.length; i++) {
            assertTrue(levels[i].error().angle() < levels[i - 1].error().angle(), levels[i].id());
            assertTrue(levels[i].error().pace() < levels[i - 1].error().pace(), levels[i].id());
            // At a hole in one too: no level goes for an ace more wildly than the one below it.
            assertTrue(levels[i].aceError().angle() <= levels[i - 1].aceError().angle(), levels[i].id());
            assertTrue(levels[i].aceError().pace() <= levels[i - 1].aceError().pace(), levels[i].id());
        }
        assertEquals(HumanError.NONE, Level.PRO.error());
        assertEquals(java.util.List.of("easy", "medium", "hard", "pro"), Level.ids());
        assertSame(Level.HARD, Level.byId("hard"));
        assertNull(Level.byId("Hard"));
    }

    @Test
    void theSameRequestGivesTheSameShotAndAnotherSeedAnother() throws Exception {
        World world = World.load(BENCH.resolve("flat-7m.json"));
        for (Level level : new Level[]{Level.EASY, Level.MEDIUM}) {
            Shot a = new LevelBot(level).nextShot(request(world, 0, 11));
            Shot b = new LevelBot(level).nextShot(request(world, 0, 11));
            Shot c = new LevelBot(level).nextShot(request(world, 0, 12));
            assertEquals(a, b, level.id());
            assertNotEquals(a, c, level.id());
        }
    }

    /**
     * The error of an attempt at a hole in one applies to a hole's first stroke when the chosen
     * shot holes, and only then: here a level exact on every other stroke, 10 degrees off on an ace.
     */
    @Test
    void theAceErrorIsPlayedOnAFirstStrokeThatWouldHoleAndNowhereElse() throws Exception {
        LevelBot acesWild = new LevelBot("aces-wild", HumanError.NONE, new HumanError(Math.toRadians(10), 0), false);
        World ace = World.load(BENCH.resolve("flat-7m.json"));
        Shot planned = new PlannerBot().nextShot(request(ace, 0, 5));
        assertTrue(CountingSimulator.holed(new CountingSimulator(ace).simulate(ace.course().start().x(),
                ace.course().start().y(), planned)), "the planner holes flat-7m in one");
        Shot struck = acesWild.nextShot(request(ace, 0, 5));
        double turn = Math.atan2(struck.vy(), struck.vx()) - Math.atan2(planned.vy(), planned.vx());
        double expected = Math.toRadians(10) * new SplittableRandom(5 ^ LevelBot.ERROR_SALT).nextGaussian();
        assertEquals(expected, turn, 1e-9, "turned by the ace error's draw");
        assertEquals(planned.speed(), struck.speed(), 1e-12);
        // Not the hole's first stroke: no attempt at an ace, the level's own (no) error.
        assertEquals(new PlannerBot().nextShot(request(ace, 1, 5)), acesWild.nextShot(request(ace, 1, 5)));
        // A first stroke that does not hole (two-putt needs two): the level's own error.
        World maze = World.load(BENCH.resolve("two-putt.json"));
        Shot layUp = new PlannerBot().nextShot(request(maze, 0, 5));
        assertTrue(!CountingSimulator.holed(new CountingSimulator(maze).simulate(maze.course().start().x(),
                maze.course().start().y(), layUp)), "two-putt's first stroke does not hole");
        assertEquals(layUp, acesWild.nextShot(request(maze, 0, 5)));
    }

    @Test
    void proPlaysThePlannersShot() throws Exception {
        World world = World.load(BENCH.resolve("maze-c.json"));
        assertEquals(new PlannerBot().nextShot(request(world, 0, 5)), new LevelBot(Level.PRO).nextShot(request(world, 0, 5)));
    }

    @Test
    void aGameIsTheSameForTheSameSeed() throws Exception {
        World world = World.load(BENCH.resolve("two-putt.json"));
        Playthrough.Result first = Playthrough.play(Bots.create("medium"), world, SimulationSettings.DEFAULT, 10, 200_000, 3,
                new CancellationToken(), BotProgress.NONE);
        Playthrough.Result again = Playthrough.play(Bots.create("medium"), world, SimulationSettings.DEFAULT, 10, 200_000, 3,
                new CancellationToken(), BotProgress.NONE);
        assertTrue(first.holed());
        assertEquals(first.strokes(), again.strokes());
        assertEquals(first.shots().stream().map(Playthrough.PlayedShot::shot).toList(),
                again.shots().stream().map(Playthrough.PlayedShot::shot).toList());
    }
}
