package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import minigolf.course.PhysicsModel;
import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Orders of accuracy, the accuracy goal, exact stops and determinism. */
class ConvergenceTest {

    /** The ball's position after exactly one second of rolling on the smooth sine course. */
    private static double[] positionAtOneSecond(Integrator integrator, int stepsPerSecond) {
        World sine = TestWorlds.world(TestWorlds.sine(), 0.05, 0.1, 20);
        Stroke stroke = new Stroke(sine, new SimulationSettings(integrator, 1.0 / stepsPerSecond, 600),
                -2, -1, 2.5, 1.5, null);
        for (int i = 0; i < stepsPerSecond; i++) stroke.step();
        assertTrue(!stroke.isFinished() && stroke.vx() != 0, "the ball must still be rolling");
        return new double[] {stroke.x(), stroke.y()};
    }

    @ParameterizedTest
    @CsvSource({"EULER, 2", "RK2, 4", "RK4, 16"})
    void halvingTheStepDividesTheErrorByTwoToTheOrder(Integrator integrator, double expectedRatio) {
        double[] reference = positionAtOneSecond(Integrator.RK4, 12800);
        double coarse = distance(positionAtOneSecond(integrator, 50), reference);
        double fine = distance(positionAtOneSecond(integrator, 100), reference);
        double ratio = coarse / fine;
        assertEquals(expectedRatio, ratio, expectedRatio * 0.15, "error " + coarse + " -> " + fine);
    }

    @Test
    void rk4AtOneSixtiethEndsWithinAMillimetreOfTheReference() {
        World sine = TestWorlds.world(TestWorlds.sine(), 0.08, 0.2, 20);
        Simulator game = TestWorlds.rk4(sine);
        Simulator reference = new Simulator(sine, SimulationSettings.DEFAULT.withDt(1e-5));
        Random random = new Random(7);
        for (int shot = 0; shot < 8; shot++) {
            double angle = random.nextDouble() * 2 * Math.PI, speed = 1 + 3 * random.nextDouble();
            ShotResult a = game.simulate(0, 0, speed * Math.cos(angle), speed * Math.sin(angle));
            ShotResult b = reference.simulate(0, 0, speed * Math.cos(angle), speed * Math.sin(angle));
            assertEquals(b.outcome(), a.outcome());
            assertTrue(Math.hypot(a.endX() - b.endX(), a.endY() - b.endY()) < 1e-3,
                    "shot " + shot + ": " + a + " vs " + b);
        }
    }

    @Test
    void everyShotOnTheLakeEndsLongBeforeTheTimeLimit() {
        World lake = TestWorlds.world(TestWorlds.lake(), 0.08, 0.2, 5);
        Simulator sim = TestWorlds.rk4(lake);
        Random random = new Random(42);
        for (int shot = 0; shot < 2000; shot++) {
            double angle = random.nextDouble() * 2 * Math.PI, speed = 5 * random.nextDouble();
            ShotResult r = sim.simulate(-3 + random.nextDouble(), random.nextDouble() - 0.5,
                    speed * Math.cos(angle), speed * Math.sin(angle));
            assertNotEquals(Outcome.TIMEOUT, r.outcome());
            assertTrue(r.time() < 30, "shot " + shot + " rolled " + r.time() + " s");
        }
    }

    @Test
    void nearCriticalSlopeStopsLikeTheContinuousModel() {
        // Down a slope of 0.099 with mu_k 0.1: deceleration only 0.00981 m/s^2.
        World plane = TestWorlds.world(TestWorlds.plane(-0.099, 0, 100), 0.1, 0.2, 100);
        ShotResult r = TestWorlds.rk4(plane).simulate(-90, 0, 0.5, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-90 + 0.25 / (2 * TestWorlds.G * 0.001), r.endX(), 1e-3);
    }

    @Test
    void theSameShotGivesBitIdenticalResults() {
        World lake = TestWorlds.world(TestWorlds.lake(), 0.08, 0.2, 5);
        Simulator sim = TestWorlds.rk4(lake);
        ShotResult first = sim.simulate(-3, 0, 3.1, 1.7);
        for (int i = 0; i < 20000; i++) sim.simulate(-3, 0, 2 + i * 1e-4, 1);
        ShotResult again = sim.simulate(-3, 0, 3.1, 1.7);
        assertEquals(Double.doubleToRawLongBits(first.endX()), Double.doubleToRawLongBits(again.endX()));
        assertEquals(Double.doubleToRawLongBits(first.endY()), Double.doubleToRawLongBits(again.endY()));
        assertEquals(first, again);
    }

    private static double distance(double[] a, double[] b) {
        return Math.hypot(a[0] - b[0], a[1] - b[1]);
    }

    @Test
    void aBallPushedUpASlopeSteeperThanKineticFrictionTurnsBackAsInTheContinuousModel() {
        // On the lake at r = 3.33 the slope is 0.083 > mu_k 0.08. Heading 11 degrees off straight
        // up, the ball's speed never falls below the rest rule's 1 mm/s as it turns: it rolls back
        // into the water at every step size.
        World lake = TestWorlds.world(TestWorlds.lake(), 0.08, 0.2, 5);
        for (double dt : new double[] {1.0 / 60, 1e-3, 1e-5}) {
            ShotResult r = new Simulator(lake, SimulationSettings.DEFAULT.withDt(dt))
                    .simulate(-3, 0, -1.053636851465158, 0.2);
            assertEquals(Outcome.WATER, r.outcome(), "dt " + dt);
            assertEquals(Math.sqrt(-8 * Math.log(0.9)), Math.hypot(r.endX(), r.endY()), 1e-6);
        }
    }

    @Test
    void aBallTurningAlmostStraightUpASlopeSteeperThanKineticFrictionStopsAtEveryStep() {
        // 1.5 degrees off straight up the same slope: its speed at the turn is far below 1 mm/s,
        // so it rests there (static friction 0.2 holds it), at the same point for every step size.
        World lake = TestWorlds.world(TestWorlds.lake(), 0.08, 0.2, 5);
        double[] reference = null;
        for (double dt : new double[] {1e-5, 1e-3, 1.0 / 60}) {
            ShotResult r = new Simulator(lake, SimulationSettings.DEFAULT.withDt(dt))
                    .simulate(-3, 0, -1.053636851465158, 0.02728162072030483);
            assertEquals(Outcome.STOPPED, r.outcome(), "dt " + dt);
            if (reference == null) reference = new double[] {r.endX(), r.endY()};
            assertEquals(0, Math.hypot(r.endX() - reference[0], r.endY() - reference[1]), 1e-5, "dt " + dt);
        }
        assertEquals(3.3322, Math.hypot(reference[0], reference[1]), 1e-4);
    }

    @Test
    void aBallRollingStraightUpASlopeBetweenTheFrictionsStopsAndStays() {
        // Slope 0.15: above mu_k 0.1, below mu_s 0.2. Straight up, v reaches 0 and static friction holds.
        World plane = TestWorlds.world(TestWorlds.plane(0.15, 0, 5), 0.1, 0.2, 20);
        ShotResult r = TestWorlds.rk4(plane).simulate(-5, 0, 2, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(-5 + 4 / (2 * TestWorlds.G * 0.25), r.endX(), 1e-9);
    }

    @Test
    void aSlowBallOnANearCriticalSlopeDoesNotCreepEvenAtTinySteps() {
        // Complete model, slope 0.0996 against mu_k 0.1: explicit friction would chatter sideways
        // and creep for ever at dt = 1e-5; the implicit slow step stops it.
        Terrain crossSlope = new Terrain() {
            public double height(double x, double y) {
                return 0.5 + 0.15 * Math.sin(0.8 * y) + 0.02 * x;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = height(x, y);
                out[1] = 0.02;
                out[2] = 0.12 * Math.cos(0.8 * y);
            }
        };
        World world = TestWorlds.world(crossSlope, 0.1, 0.25, 6, PhysicsModel.COMPLETE, TestWorlds.farHole(6), List.of());
        ShotResult reference = new Simulator(world, SimulationSettings.DEFAULT.withDt(1e-5))
                .simulate(-4, -3, 0.2719865323628711, -0.7444444263380493);
        assertEquals(Outcome.STOPPED, reference.outcome());
        assertTrue(reference.time() < 3, "stopped after " + reference.time() + " s");
        ShotResult game = TestWorlds.rk4(world).simulate(-4, -3, 0.2719865323628711, -0.7444444263380493);
        assertEquals(0, Math.hypot(game.endX() - reference.endX(), game.endY() - reference.endY()), 5e-3);
    }
}
