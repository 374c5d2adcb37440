package minigolf.physics;

import static minigolf.physics.TestWorlds.G;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.Shape;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Motions with exact answers: the engine must reproduce them to well under a millimetre. */
class ClosedFormTest {
    private static final double MM = 1e-3;

    @Test
    void flatGroundStopsAfterVSquaredOverTwoMuG() {
        World flat = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20);
        ShotResult r = TestWorlds.rk4(flat).simulate(-10, 0, 5, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-10 + 12.742099898063200, r.endX(), MM);
        assertEquals(0, r.endY(), 1e-12);
        assertEquals(5.0968399592252800, r.time(), 1e-6);
    }

    @ParameterizedTest
    @EnumSource(value = Integrator.class, names = {"RK2", "RK4"})
    void flatStopIsExactForEveryStepSize(Integrator integrator) {
        World flat = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20);
        for (double dt : new double[] {1.0 / 30, 1.0 / 60, 1.0 / 240, 0.01}) {
            Simulator sim = new Simulator(flat, SimulationSettings.DEFAULT.withIntegrator(integrator).withDt(dt));
            ShotResult r = sim.simulate(-10, 0, 3, 4);
            double distance = 25 / (2 * 0.1 * G);
            assertEquals(-10 + distance * 0.6, r.endX(), 1e-9, "dt " + dt);
            assertEquals(distance * 0.8, r.endY(), 1e-9, "dt " + dt);
        }
    }

    @Test
    void upAUniformSlopeStopsAfterVSquaredOverTwoGTimesSlopePlusMu() {
        double slope = 0.05, mu = 0.1;
        World plane = TestWorlds.world(TestWorlds.plane(slope, 0, 1), mu, 0.2, 20);
        ShotResult r = TestWorlds.rk4(plane).simulate(-5, 0, 3, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-5 + 9 / (2 * G * (slope + mu)), r.endX(), MM);
        assertEquals(3 / (G * (slope + mu)), r.time(), 1e-6);
    }

    @Test
    void completeModelUpASlopeIncludesTheNormalisation() {
        double slope = 0.3, mu = 0.1;
        World plane = TestWorlds.world(TestWorlds.plane(slope, 0, 5), mu, 0.4, 20, PhysicsModel.COMPLETE,
                TestWorlds.farHole(20), List.of());
        ShotResult r = TestWorlds.rk4(plane).simulate(-5, 0, 3, 0);
        assertEquals(-5 + 9 * (1 + slope * slope) / (2 * G * (slope + mu)), r.endX(), MM);
    }

    @Test
    void completeModelEqualsClassicOnFlatGround() {
        World classic = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20);
        World complete = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.COMPLETE,
                TestWorlds.farHole(20), List.of());
        ShotResult a = TestWorlds.rk4(classic).simulate(0, 0, 2, -1);
        ShotResult b = TestWorlds.rk4(complete).simulate(0, 0, 2, -1);
        assertEquals(a, b);
    }

    @Test
    void ballOnSlopeSteeperThanStaticFrictionRollsDownWithGTimesSlopeMinusMu() {
        double slope = 0.3, muK = 0.1, muS = 0.2;
        World steep = TestWorlds.world(TestWorlds.plane(slope, 0, 10), muK, muS, 20);
        List<double[]> path = new ArrayList<>();
        ShotResult r = TestWorlds.rk4(steep).simulate(0, 0, 0, 0, (t, x, y, vx, vy) -> path.add(new double[] {t, x, vx}));
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(-20, r.endX(), MM);
        double a = G * (slope - muK);
        for (double[] p : path.subList(0, path.size() - 1)) {
            assertEquals(-0.5 * a * p[0] * p[0], p[1], 1e-9);
            assertEquals(-a * p[0], p[2], 1e-9);
        }
        assertEquals(Math.sqrt(2 * 20 / a), r.time(), 1e-6);
    }

    @Test
    void ballOnSlopeFlatterThanStaticFrictionStays() {
        World gentle = TestWorlds.world(TestWorlds.plane(0.15, 0, 10), 0.1, 0.2, 20);
        ShotResult r = TestWorlds.rk4(gentle).simulate(1, 2, 0, 0);
        assertEquals(new ShotResult(Outcome.STOPPED, 1, 2, 0, 0, 0.15 + 10, java.util.List.of()), r);
    }

    @Test
    void ballStoppingOnSteepSlopeRollsBackDown() {
        // Up a slope of 0.3 with mu_s 0.2: it stops, then rolls back down and leaves the course.
        World steep = TestWorlds.world(TestWorlds.plane(0.3, 0, 10), 0.1, 0.2, 20);
        ShotResult r = TestWorlds.rk4(steep).simulate(0, 0, 2, 0);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(-20, r.endX(), MM);
        double up = 4 / (2 * G * 0.4);
        double tUp = 2 / (G * 0.4);
        double tDown = Math.sqrt(2 * (20 + up) / (G * 0.2));
        assertEquals(tUp + tDown, r.time(), 1e-6);
    }

    @Test
    void waterEntryOnAPlaneIsLocatedInsideTheStep() {
        // h = 0.1 x + 0.2: water for x < -2. Rolling downhill with mu 0.2: deceleration g (0.2 - 0.1).
        World plane = TestWorlds.world(TestWorlds.plane(0.1, 0, 0.2), 0.2, 0.3, 20);
        ShotResult r = TestWorlds.rk4(plane).simulate(0, 1, -3, 0);
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(-2, r.endX(), 1e-6);
        assertEquals(1, r.endY(), 1e-12);
        double a = G * 0.1;
        assertEquals((3 - Math.sqrt(9 - 2 * a * 2)) / a, r.time(), 1e-6);
    }

    @ParameterizedTest
    @EnumSource(Integrator.class)
    void leavingTheBoundsIsLocatedOnTheEdge(Integrator integrator) {
        World flat = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 5);
        Simulator sim = new Simulator(flat, SimulationSettings.DEFAULT.withIntegrator(integrator));
        ShotResult r = sim.simulate(0, 0, 3, 4);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(5, r.endY(), 1e-6);
        assertEquals(3.75, r.endX(), integrator == Integrator.EULER ? 1e-2 : 1e-6);
    }

    @Test
    void sandZoneUsesItsOwnFriction() {
        Zone sand = new Zone(new Shape.Rect(new Vec2(-20, -20), new Vec2(20, 20)), 0.5, 0.6);
        World world = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.CLASSIC,
                TestWorlds.farHole(20), List.of(sand));
        ShotResult r = TestWorlds.rk4(world).simulate(0, 0, 3, 0);
        assertEquals(9 / (2 * 0.5 * G), r.endX(), MM);
    }

    @Test
    void crossingIntoASandZoneSplitsTheStepAtTheEdge() {
        // Grass (mu 0.1) up to x = 1.003, sand (mu 0.5) beyond: v1^2 = v0^2 - 2 mu1 g d, then v1^2 / (2 mu2 g).
        Zone sand = new Zone(new Shape.Rect(new Vec2(1.003, -20), new Vec2(20, 20)), 0.5, 0.6);
        World world = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.CLASSIC,
                TestWorlds.farHole(20), List.of(sand));
        double v1Squared = 9 - 2 * 0.1 * G * 1.003;
        ShotResult r = TestWorlds.rk4(world).simulate(0, 0, 3, 0);
        assertEquals(1.003 + v1Squared / (2 * 0.5 * G), r.endX(), 1e-9);
        double time = (3 - Math.sqrt(v1Squared)) / (0.1 * G) + Math.sqrt(v1Squared) / (0.5 * G);
        assertEquals(time, r.time(), 1e-9);
    }

    @Test
    void restRuleHolesABallThatStopsInsideTheRadius() {
        double distance = 4 / (2 * 0.1 * G);
        Hole hole = new Hole(new Vec2(distance + 0.05, 0), 0.1, HoleRule.REST, null);
        World world = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.CLASSIC, hole, List.of());
        assertEquals(Outcome.HOLED, TestWorlds.rk4(world).simulate(0, 0, 2, 0).outcome());
        assertEquals(Outcome.STOPPED, TestWorlds.rk4(world).simulate(0, 0, 1.9, 0).outcome());
        // Rolling over the hole is not enough under the rest rule.
        assertEquals(Outcome.STOPPED, TestWorlds.rk4(world).simulate(0, 0, 3, 0).outcome());
    }

    @Test
    void captureRuleDropsSlowBallsAndLetsFastOnesPass() {
        Hole hole = new Hole(new Vec2(1, 0), 0.054, HoleRule.CAPTURE, null);
        World world = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20, PhysicsModel.CLASSIC, hole, List.of());
        assertEquals(1.31, hole.effectiveCaptureSpeed(), 1e-12);
        // Speed over the centre: sqrt(v0^2 - 2 mu g d).
        double slowLaunch = Math.sqrt(1.2 * 1.2 + 2 * 0.1 * G);
        ShotResult slow = TestWorlds.rk4(world).simulate(0, 0, slowLaunch, 0);
        assertEquals(Outcome.HOLED, slow.outcome());
        assertEquals(1, slow.endX(), 1e-9);
        double fastLaunch = Math.sqrt(1.4 * 1.4 + 2 * 0.1 * G);
        assertEquals(Outcome.STOPPED, TestWorlds.rk4(world).simulate(0, 0, fastLaunch, 0).outcome());
        // Off-centre by half the radius the limit is 1.31 * 0.75 = 0.98 m/s.
        ShotResult offCentre = TestWorlds.rk4(world).simulate(0, 0.027, Math.sqrt(1.1 * 1.1 + 2 * 0.1 * G), 0);
        assertEquals(Outcome.STOPPED, offCentre.outcome());
        ShotResult offCentreSlow = TestWorlds.rk4(world).simulate(0, 0.027, Math.sqrt(0.9 * 0.9 + 2 * 0.1 * G), 0);
        assertEquals(Outcome.HOLED, offCentreSlow.outcome());
    }

    @Test
    void shotsAboveMaxSpeedAreRefused() {
        World flat = TestWorlds.world(TestWorlds.plane(0, 0, 0.1), 0.1, 0.2, 20);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TestWorlds.rk4(flat).simulate(0, 0, 4, 3.1));
        assertTrue(e.getMessage().contains("shot speed 5.061 m/s exceeds the course's maxSpeed of 5.0 m/s"), e.getMessage());
        assertEquals(Outcome.STOPPED, TestWorlds.rk4(flat).simulate(0, 0, 3, 4).outcome());
    }
}
