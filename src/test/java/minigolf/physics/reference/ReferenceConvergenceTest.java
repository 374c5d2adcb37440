package minigolf.physics.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import minigolf.course.CourseException;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The reference has converged: at a 100 times tighter tolerance (1e-12 per step) its end points
 * move by less than a micrometre, a thousand times below the 1 mm the engine is held to.
 */
class ReferenceConvergenceTest {
    @ParameterizedTest
    @ValueSource(strings = {"lake.json", "sine-hills.json", "sand.json", "grid-hills.json", "walled.json"})
    void aHundredTimesTighterToleranceMovesNoEndPointByAMicrometre(String name) throws CourseException {
        World world = EngineAgreementTest.course(name);
        ReferenceSimulator usual = new ReferenceSimulator(world);
        ReferenceSimulator tight = new ReferenceSimulator(world, SimulationSettings.DEFAULT_MAX_TIME, 1e-12);
        SplittableRandom random = new SplittableRandom(5);
        double x0 = world.course().start().x(), y0 = world.course().start().y(), max = world.physics().maxSpeed();
        int compared = 0;
        for (int i = 0; i < 40; i++) {
            double angle = random.nextDouble() * 2 * Math.PI, speed = max * (0.1 + 0.9 * random.nextDouble());
            double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
            ReferenceResult a = usual.simulate(x0, y0, vx, vy), b = tight.simulate(x0, y0, vx, vy);
            if (!a.covered() || !b.covered()) continue;
            compared++;
            assertEquals(a.outcome(), b.outcome(), "shot " + vx + ", " + vy);
            assertEquals(0, Math.hypot(a.endX() - b.endX(), a.endY() - b.endY()), 1e-6, "shot " + vx + ", " + vy);
        }
        assertTrue(compared >= 36, "compared " + compared);
    }
}
