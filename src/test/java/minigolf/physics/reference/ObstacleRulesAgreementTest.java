package minigolf.physics.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.CourseException;
import minigolf.course.Obstacle;
import minigolf.course.Vec3;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.StrokeEvent;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Where the engine and the independent reference once applied the obstacle rules of
 * docs/physics.md differently: settling on an obstacle's top, and the rest rule's decision about
 * a turn after a contact. Each is a real shot of `bench-accuracy COURSE --shots 1000` (seed 1)
 * or a closed case.
 */
class ObstacleRulesAgreementTest {
    private static ShotResult engine(World world, double vx, double vy) {
        return new Simulator(world, SimulationSettings.DEFAULT)
                .simulate(world.course().start().x(), world.course().start().y(), vx, vy, 0, null);
    }

    private static ReferenceResult reference(World world, double vx, double vy) {
        ReferenceResult r = new ReferenceSimulator(world)
                .simulate(world.course().start().x(), world.course().start().y(), vx, vy);
        assertTrue(r.covered(), r.note());
        return r;
    }

    /**
     * `maze-b-hills` shot 796 jumps onto a wall's top and skims along it at 1.5 m/s, bouncing
     * lower each time. By the rule it settles (out) at the first contact it leaves slower than a
     * 1 mm hop; the engine once went on until 16 contacts in one step stopped it, 71 mm further.
     */
    @Test
    void aBallSkimmingAlongAWallTopIsOutWhereItFirstSettles() throws CourseException {
        World world = EngineAgreementTest.course("bench/maze-b-hills.json");
        double vx = -0.65102455516886000, vy = -4.8921432688119060;
        ShotResult e = engine(world, vx, vy);
        ReferenceResult r = reference(world, vx, vy);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(Outcome.OUT, e.outcome());
        assertEquals(0, Math.hypot(e.endX() - r.endX(), e.endY() - r.endY()), 1e-5, e + " vs " + r);
        long contacts = e.events().stream().filter(ev -> ev.type() == StrokeEvent.Type.COLLISION).count();
        assertEquals(3, contacts, e.events().toString());
        assertEquals(3, r.contacts());
    }

    /**
     * A chip onto a long box's top (no drag, restitution 0.7): it comes down at
     * vn = √(2g·0.2 m) = 1.98 m/s, keeps 0.7 of it at each bounce and settles, out, at the
     * first contact it leaves slower than a 1 mm hop (the 8th: 0.7⁸·1.98 = 0.114 m/s, below
     * √(2g·1 mm) = 0.140 m/s), however fast it moves along the top (1 m/s).
     */
    @Test
    void aChipSettlesOnABoxTopAtTheFirstBounceBelowAMillimetreHop() {
        World flat = ReferenceWorlds.flightWorld(ReferenceWorlds.plane(0, 0.1), 0.1, 20, 0, null);
        World box = new World(flat.course().withObstacles(List.of(
                new Obstacle.Box(new Vec3(-2.6, -1, -1), new Vec3(0.5, 1, 0.4), 0, 0.7))), flat.terrain());
        double vz = Math.sqrt(2 * ReferenceWorlds.G * 0.5);
        ShotResult e = new Simulator(box, SimulationSettings.DEFAULT).simulate(-3, 0, 1, 0, vz, null);
        ReferenceResult r = new ReferenceSimulator(box).simulate(-3, 0, 1, 0, vz);
        double vn = Math.sqrt(2 * ReferenceWorlds.G * 0.2), hop = Math.sqrt(2 * ReferenceWorlds.G * 1e-3);
        // Closed form: the first contact where the parabola's bottom reaches the top (0.3 m above
        // the ground), then flights of 2·e^k·vn/g at 1 m/s along it.
        double g = ReferenceWorlds.G, x = -3 + (vz + Math.sqrt(vz * vz - 2 * g * 0.3)) / g;
        int bounces = 1;
        while (0.7 * vn >= hop) {
            vn *= 0.7;
            x += 2 * vn / g;
            bounces++;
        }
        assertEquals(Outcome.OUT, e.outcome(), e.toString());
        assertEquals(Outcome.OUT, r.outcome(), r.toString());
        long contacts = e.events().stream().filter(ev -> ev.type() == StrokeEvent.Type.COLLISION).count();
        assertEquals(bounces, contacts, e.events().toString());
        assertEquals(bounces, r.contacts());
        assertEquals(8, bounces);
        assertEquals(x, r.endX(), 1e-9);
        // The engine's contacts lie on chords of 1/64 of a step, each some 0.3 µm early here.
        assertEquals(x, e.endX(), 1e-5);
        assertTrue(e.endX() > -2.6 && e.endX() < 0.5, "on the top: " + e);
    }

    /**
     * `lake-obstacles` shot 664 meets a wall at 0.07 m/s, braking on a slope steeper than μk,
     * and stops near it. The engine once kept the decision about the turn ahead that it had taken
     * before the contact, for the old heading (roll back down), and ended 4.3 mm from the
     * reference (0.35 m since a ball settles against a wall).
     */
    @Test
    void theRestRuleDecidesATurnAfreshAfterAContact() throws CourseException {
        World world = EngineAgreementTest.course("lake-obstacles.json");
        double vx = 0.94493422765745040, vy = 4.6965861167457040;
        ShotResult e = engine(world, vx, vy);
        ReferenceResult r = reference(world, vx, vy);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(Outcome.STOPPED, e.outcome());
        assertEquals(0, Math.hypot(e.endX() - r.endX(), e.endY() - r.endY()), 1e-4, e + " vs " + r);
    }
}
