package minigolf.physics.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.course.CourseException;
import minigolf.physics.Outcome;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Ill-conditioned shots, measured with the reference alone, on real shots of `lake-obstacles`. */
class ConditioningTest {
    private static double spread(World world, ReferenceSimulator reference, double vx, double vy) {
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        return Conditioning.spread(reference, x0, y0, vx, vy, reference.simulate(x0, y0, vx, vy));
    }

    /**
     * Shot 74 (seed 1) glances off two obstacles and stops on the shore; 1e-7 m/s more or less in
     * either component of its velocity and it rolls into the lake, a metre away: no integrator can
     * be held to 1 mm there.
     */
    @Test
    void aShotThatStopsOrRollsIntoTheLakeIsIllConditioned() throws CourseException {
        World world = EngineAgreementTest.course("lake-obstacles.json");
        ReferenceSimulator reference = new ReferenceSimulator(world);
        double vx = 0.79927784688670780, vy = -1.4252319781449125;
        double x0 = world.course().start().x(), y0 = world.course().start().y();
        assertEquals(Outcome.STOPPED, reference.simulate(x0, y0, vx, vy).outcome());
        assertNotEquals(Outcome.STOPPED, reference.simulate(x0, y0, vx + Conditioning.PERTURBATION, vy).outcome());
        double spread = spread(world, reference, vx, vy);
        assertTrue(spread > 1, "spread " + spread + " m");
        assertTrue(Conditioning.illConditioned(spread));
    }

    /** Shot 664 (6 contacts, a stop after a wall) and a plain shot are well conditioned. */
    @Test
    void otherShotsAreWellConditioned() throws CourseException {
        World world = EngineAgreementTest.course("lake-obstacles.json");
        ReferenceSimulator reference = new ReferenceSimulator(world);
        double s664 = spread(world, reference, 0.94493422765745040, 4.6965861167457040);
        assertTrue(s664 < 0.5e-3, "spread " + s664 + " m");
        assertFalse(Conditioning.illConditioned(s664));
        World lake = EngineAgreementTest.course("lake.json");
        double plain = spread(lake, new ReferenceSimulator(lake), 1.5, -0.7);
        assertTrue(plain < 1e-5, "spread " + plain + " m");
    }
}
