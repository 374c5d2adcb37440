package minigolf.physics.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.CourseException;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsSettings;
import minigolf.course.Vec2;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.StrokeEvent;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A ball that the slope presses against a wall settles against it and rolls along it
 * (docs/physics.md, "Rolling along an obstacle"), in the engine and in the reference alike.
 */
class LeaningTest {
    private static final double MU_K = 0.1, SLOPE = 0.3, R = PhysicsSettings.DEFAULT_BALL_RADIUS;
    /** The wall's face towards the ball: a wall along x = −1, 0.1 m thick, from y = −5 to y = 0. */
    private static final double FACE = -0.95;

    /** h = 0.3x + 4 (steeper than μs = 0.2): the ground pulls the ball towards −x, into the wall. */
    private static World slopeIntoWall() {
        World w = ReferenceWorlds.world(ReferenceWorlds.plane(SLOPE, 4), MU_K, 0.2, 20);
        return new World(w.course().withObstacles(List.of(
                new Obstacle.Wall(new Vec2(-1, -5), new Vec2(-1, 0), 0.1, 0.2, 0.7))), w.terrain());
    }

    private static long contacts(ShotResult r) {
        return r.events().stream().filter(e -> e.type() == StrokeEvent.Type.COLLISION).count();
    }

    /**
     * A ball 1 µm from the wall, rolling along it at v: it touches at 2.4 mm/s, settles, and
     * brakes along the wall to a stop v²/(2μk·g) further, held there by the wall (rule 2). Before,
     * the engine bounced it ever lower until 16 contacts in one step stopped it where it was, and
     * the reference gave up after 1,000 contacts.
     */
    @ParameterizedTest
    @ValueSource(doubles = {0.5, 1.5})
    void aBallPressedAgainstAWallBrakesAlongIt(double v) {
        World world = slopeIntoWall();
        double x0 = FACE + R + 1e-6, y0 = -4;
        ShotResult e = new Simulator(world, SimulationSettings.DEFAULT).simulate(x0, y0, 0, v, 0, null);
        ReferenceResult r = new ReferenceSimulator(world).simulate(x0, y0, 0, v);
        double stop = y0 + v * v / (2 * MU_K * ReferenceWorlds.G);
        assertTrue(r.covered(), r.note());
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(Outcome.STOPPED, e.outcome(), e.toString());
        assertEquals(stop, r.endY(), 1e-8);
        assertEquals(stop, e.endY(), 1e-8);
        assertEquals(FACE + R, r.endX(), 1e-8);
        assertEquals(FACE + R, e.endX(), 1e-6);
        assertEquals(1, r.contacts());
        assertEquals(1, contacts(e), e.events().toString());
    }

    /**
     * Fast enough to pass the wall's end (y = 0.05), the ball leaves it there and rolls down the
     * slope round the end into the water (h = 0 at x = −13.3); the engine and the reference leave at the same
     * moment and agree to a micrometre.
     */
    @Test
    void aBallLeavesTheWallAtItsEnd() {
        World world = slopeIntoWall();
        double x0 = FACE + R + 1e-6, y0 = -4;
        ShotResult e = new Simulator(world, SimulationSettings.DEFAULT).simulate(x0, y0, 0, 3, 0, null);
        ReferenceResult r = new ReferenceSimulator(world).simulate(x0, y0, 0, 3);
        assertTrue(r.covered(), r.note());
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(Outcome.WATER, e.outcome(), e.toString());
        assertEquals(-4 / SLOPE, r.endX(), 1e-9);
        assertTrue(r.endY() > 0.05, r.toString());
        assertEquals(0, Math.hypot(e.endX() - r.endX(), e.endY() - r.endY()), 1e-6, e + " vs " + r);
    }

    /**
     * Bundled courses where the reference once gave up on balls left leaning on a wall (more than
     * 1,000 contacts: 11 of 1,000 seeded shots on `maze-b-hills`, 31 on `14-waves`, 41 on
     * `lake-obstacles`): it now covers every shot of the first 200, and the engine agrees.
     */
    @ParameterizedTest
    @ValueSource(strings = {"bench/maze-b-hills.json", "holes/14-waves.json"})
    void theReferenceCoversBallsLeaningOnWalls(String name) throws CourseException {
        World world = EngineAgreementTest.course(name);
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        ReferenceSimulator reference = new ReferenceSimulator(world);
        java.util.SplittableRandom random = new java.util.SplittableRandom(1);
        double x0 = world.course().start().x(), y0 = world.course().start().y(), max = world.physics().maxSpeed();
        int within = 0;
        for (int i = 0; i < 200; i++) {
            double angle = random.nextDouble() * 2 * Math.PI, speed = max * (0.1 + 0.9 * random.nextDouble());
            double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
            ReferenceResult r = reference.simulate(x0, y0, vx, vy);
            assertTrue(r.covered(), "shot " + i + ": " + r.note());
            ShotResult s = engine.simulate(x0, y0, vx, vy);
            if (Math.hypot(s.endX() - r.endX(), s.endY() - r.endY()) <= 1e-3) within++;
        }
        assertTrue(within >= 199, within + " of 200 within 1 mm");
    }
}
