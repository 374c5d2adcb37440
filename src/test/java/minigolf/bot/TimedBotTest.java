package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.bot.play.Bots;
import minigolf.bot.play.Playthrough;
import minigolf.bot.play.TimedBot;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The wait before a shot where obstacles move (issue 24): {@link TimedBot} asks the bot it wraps at
 * moments spread over the period and plays the first shot that holes, after its wait.
 */
class TimedBotTest {
    static World slidingGate() throws Exception {
        return World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "src", "test", "resources", "elements",
                "sliding-gate.json"));
    }

    /** Always the same putt straight at the hole, 3.5 m/s: it drops (capture rule) if nothing is in the way. */
    static final Bot STRAIGHT = new Bot() {
        public String name() {
            return "straight";
        }

        public Shot nextShot(BotRequest request) {
            return Shot.of(3.5, 0);
        }
    };

    @Test
    void theWaitLetsAStraightPuttThroughTheSlidingGate() throws Exception {
        World w = slidingGate();
        Simulator engine = new Simulator(w, SimulationSettings.DEFAULT);
        // Played at once the gate is in the way (it slides out of the lane over the first second).
        assertNotEquals(Outcome.HOLED, engine.simulateAt(0, -3, 0, 3.5, 0, 0).outcome());
        CountingSimulator sim = new CountingSimulator(w);
        Shot shot = new TimedBot(STRAIGHT).nextShot(new BotRequest(sim, -3, 0, 0, 1, NoiseModel.NONE, 0));
        // The first of the eight moments of the 4 s period that holes: half a second later.
        assertEquals(0.5, shot.waitSeconds());
        assertEquals(Outcome.HOLED, engine.simulateAt(0.5, -3, 0, shot.vx(), shot.vy(), 0).outcome());
        assertEquals(2, sim.count(), "the shot of each of the two moments tried simulated once");
        // From another moment of the clock the same bot waits otherwise.
        Shot later = new TimedBot(STRAIGHT).nextShot(new BotRequest(new CountingSimulator(w), -3, 0, 0, 1, NoiseModel.NONE, 3.3));
        assertEquals(Outcome.HOLED, engine.simulateAt(3.3 + later.waitSeconds(), -3, 0, later.vx(), later.vy(), 0).outcome());
    }

    @Test
    void aPlaythroughRunsTheClockThroughWaitsAndStrokes() throws Exception {
        World w = slidingGate();
        Playthrough.Result r = Playthrough.play(STRAIGHT, w, SimulationSettings.DEFAULT, 3, 1000, 1,
                CancellationToken.none(), BotProgress.NONE);
        assertTrue(r.holed());
        assertEquals(1, r.strokes());
        assertEquals(0.5, r.shots().get(0).intended().waitSeconds());
        // Every bot plays it (the planner holes it).
        Playthrough.Result planner = Playthrough.play(Bots.create("planner"), w, SimulationSettings.DEFAULT, 4, 20_000, 1,
                CancellationToken.withTimeLimit(60), BotProgress.NONE);
        assertTrue(planner.holed());
    }

    @Test
    void whereNothingMovesTheBotIsUnchanged() throws Exception {
        World still = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json"));
        assertSame(STRAIGHT, TimedBot.forWorld(STRAIGHT, still));
        assertTrue(TimedBot.forWorld(STRAIGHT, slidingGate()) instanceof TimedBot);
    }
}
