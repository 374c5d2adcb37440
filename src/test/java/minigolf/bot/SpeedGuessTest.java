package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;

import minigolf.bot.search.SpeedGuess;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The energy estimate against closed forms and the engine. */
class SpeedGuessTest {
    @Test
    void flatGroundClosedForms() {
        // 5 m/s at mu_k 0.1 stops after v^2 / (2 mu g) = 12.7421 m.
        assertEquals(12.7421, SpeedGuess.roll(9.81, 0.1, 5, 0), 1e-4);
        assertEquals(25, SpeedGuess.speedSquared(9.81, 0.1, 12.742099898063201, 0), 1e-9);
    }

    @Test
    void upAUniformSlopeTheRollIsVSquaredOverTwoGTimesSlopePlusFriction() {
        // Up a slope s the roll L drops -s L: L = v^2 / (2 g (s + mu)); 3 m/s, s 0.05, mu 0.1: 3.0581 m.
        double length = 9 / (2 * 9.81 * 0.15);
        assertEquals(3.0581, length, 1e-4);
        assertEquals(length, SpeedGuess.roll(9.81, 0.1, 3, -0.05 * length), 1e-12);
        assertEquals(9, SpeedGuess.speedSquared(9.81, 0.1, length, 0.05 * length), 1e-12);
    }

    @Test
    void theGuessForSevenMetresOnTheFlatCourseStopsOnTheHoleInTheEngine() {
        World flat = BenchCourses.load("flat-7m");
        double v = SpeedGuess.speed(flat, -3.5, 0, 7, 3.5, 0, 0.01);
        assertEquals(Math.sqrt(2 * 9.81 * 0.1 * 7), v, 1e-12);
        ShotResult r = new Simulator(flat, SimulationSettings.DEFAULT).simulate(-3.5, 0, v, 0);
        assertEquals(3.5, r.endX(), 1e-3);
        assertEquals(5 * 5 / (2 * 9.81 * 0.1), SpeedGuess.maxRoll(flat, -3.5, 0, 3.5, 0), 1e-12);
    }

    @Test
    void noFrictionCountsAsALittleAndAShotThatStaysPutIsRaised() {
        assertEquals(SpeedGuess.roll(9.81, SpeedGuess.MIN_FRICTION, 5, 0),
                SpeedGuess.maxRoll(BotRobustnessTest.course("no friction", "0", 0, 0, 5, 0.02135, ""), -3, 0, 3, 0), 1e-9);
        // Downhill more than friction eats: the energy says no push at all; the floor keeps 0.2 m/s.
        World steep = BotRobustnessTest.course("downhill", "1-0.3*x", 0.1, 0.2, 5, 0.02135, "");
        assertEquals(0.2, SpeedGuess.speed(steep, -3, 0, 1, -2, 0, 0.04), 1e-12);
    }
}
