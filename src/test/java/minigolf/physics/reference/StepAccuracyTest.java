package minigolf.physics.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.CourseException;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.Stroke;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Shots of `minigolf bench-accuracy COURSE --shots 1000` (seed 1) that RK4 at 1/60 s once ended
 * millimetres from the independent reference, each for its own cause (docs/measurements.md, "Accuracy against
 * an independent reference"): now within 1 mm.
 */
class StepAccuracyTest {

    @ParameterizedTest(name = "{0} ({3})")
    @CsvSource({
            // A 256^2 bicubic grid: the curvature jumps at every cell edge inside a step (was 4.4 mm).
            "grid-256.json, 3.929337553855547, 2.735932636551539, step control",
            "grid-256.json, 4.411483255184929, 0.6751820386084834, step control",
            // Slopes near mu_k: a long, slow roll in the first-order slow step (was 65 mm).
            "sine-cross.json, 0.8546879432533632, 2.134441644078604, slow step at 1/8 of its speed",
            "sine-cross.json, 0.2613646568165874, -0.8316203245581302, slow step at 1/8 of its speed",
            // Glancing contacts with trunks, found on a chord that cut the path's corner (was 4.2 mm).
            "trees.json, 4.141047544424711, 0.8253635536463453, contact on the path",
            "bench/tree-field.json, 4.802536869687046, 1.3543993086246682, contact on the path",
            // A marginal crest: launched where the probe saw it, ahead of v^T H v = -g (was 27 mm).
            "holes/12-two-tiers.json, 4.469974212915726, -0.9471722135975259, take-off at the criterion",
            "holes/12-two-tiers.json, 4.645296714481845, 0.3849589968131288, take-off at the criterion"})
    void engineEndsWithinOneMillimetreOfTheReference(String course, double vx, double vy, String cause)
            throws CourseException {
        World world = EngineAgreementTest.course(course);
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        ShotResult e = new Simulator(world, SimulationSettings.DEFAULT).simulate(x0, y0, vx, vy);
        ReferenceResult r = new ReferenceSimulator(world).simulate(x0, y0, vx, vy);
        assertTrue(r.covered(), r.note());
        assertEquals(r.outcome(), e.outcome());
        double error = Math.hypot(e.endX() - r.endX(), e.endY() - r.endY());
        assertTrue(error < 1e-3, course + ": " + error * 1e3 + " mm from the reference");
    }

    /** Frames are not steps: every step() shows the ball exactly dt later, whatever steps the control took. */
    @Test
    void everyFrameIsDtLaterWhateverTheSteps() throws CourseException {
        World grid = EngineAgreementTest.course("grid-256.json");
        double dt = SimulationSettings.DEFAULT.dt();
        Stroke stroke = new Stroke(grid, SimulationSettings.DEFAULT, grid.course().start().x(),
                grid.course().start().y(), 3.929337553855547, 2.735932636551539, null);
        int frames = 0;
        while (!stroke.isFinished() && frames < 120) {
            stroke.step();
            frames++;
            if (!stroke.isFinished()) assertEquals(frames * dt, stroke.time(), 1e-12, "frame " + frames);
        }
        assertTrue(stroke.steps() > frames, "the control took sub-steps: " + stroke.steps() + " in " + frames + " frames");
    }
}
