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

    @Test
    void aBallReachingTerrainThatIsNotFiniteIsOutOfPlayInsteadOfACrash() throws Exception {
        // sqrt of a negative number for |x - 0.1| < 0.01: between the loader's 33 x 33 samples.
        String json = new String(java.nio.file.Files.readAllBytes(java.nio.file.Path.of("courses/flat.json")))
                .replace("\"height\": \"0.1\"", "\"height\": \"sqrt(abs(x - 0.1) - 0.01) + 1\"");
        minigolf.physics.World world = minigolf.physics.World.parse(json, "nan.json");
        StrokeAnimator a = new StrokeAnimator(new Stroke(world, SIM, -3, 0, 4, 0, null), SIM.dt());
        java.io.PrintStream stderr = System.err;
        java.io.ByteArrayOutputStream said = new java.io.ByteArrayOutputStream();
        System.setErr(new java.io.PrintStream(said, true));
        try {
            for (int frame = 0; frame < 600 && !a.isFinished(); frame++) a.advance(1 / 60.0, 1);
        } finally {
            System.setErr(stderr);
        }
        assertTrue(a.isFinished());
        assertEquals(minigolf.physics.Outcome.OUT, a.stroke().result().outcome());
        assertTrue(Double.isFinite(a.x()) && Double.isFinite(a.y()));
        assertTrue(said.toString().contains("not finite") || said.toString().contains("overflows"), said.toString());
    }
}
