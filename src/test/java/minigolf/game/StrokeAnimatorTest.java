package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.Stroke;
import org.junit.jupiter.api.Test;

class StrokeAnimatorTest {
    private static final SimulationSettings SIM = SimulationSettings.DEFAULT;

    private static Stroke stroke() {
        return new Stroke(GameTest.FLAT, SIM, -3, 0, 3, 0.4, null);
    }

    @Test
    void frameRateDoesNotChangeTheShot() {
        ShotResult reference = new Simulator(GameTest.FLAT, SIM).simulate(-3, 0, 3, 0.4);
        for (double frame : new double[]{1 / 144.0, 1 / 60.0, 1 / 23.0}) {
            StrokeAnimator a = new StrokeAnimator(stroke(), SIM.dt());
            int frames = 0;
            while (!a.isFinished()) {
                a.advance(frame, 1);
                frames++;
            }
            assertEquals(reference, a.stroke().result(), "frame " + frame);
            assertEquals(reference.endX(), a.x(), 0.0);
            assertTrue(Math.abs(frames * frame - reference.time()) < 0.1, frames * frame + " s for " + reference.time());
        }
    }

    @Test
    void drawsBetweenTheLastTwoStates() {
        StrokeAnimator a = new StrokeAnimator(stroke(), SIM.dt());
        assertEquals(0, a.advance(0.5 * SIM.dt(), 1));
        assertEquals(-3, a.x(), 1e-12, "no step yet, nothing to interpolate");
        assertEquals(1, a.advance(0.75 * SIM.dt(), 1), "1.25 steps of time: one step");
        double x1 = a.stroke().x();
        // a quarter of a step is left over: a quarter of the way from the start to the first state
        assertEquals(-3 + 0.25 * (x1 + 3), a.x(), 1e-12);
        // on flat ground the acceleration is mu g against the motion
        assertEquals(0.1 * 9.81, Math.hypot(a.ax(), a.ay()), 1e-9);
    }

    @Test
    void aLongFrameTakesAtMostThirtySteps() {
        StrokeAnimator a = new StrokeAnimator(stroke(), SIM.dt());
        assertEquals(StrokeAnimator.MAX_STEPS_PER_FRAME, a.advance(10, 1));
        assertEquals(2, a.advance(2 * SIM.dt() + 1e-9, 1), "the backlog was dropped");
    }
}
