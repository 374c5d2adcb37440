package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import minigolf.course.PhysicsModel;
import minigolf.physics.reference.ReferenceResult;
import minigolf.physics.reference.ReferenceSimulator;
import minigolf.terrain.Terrain;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Orders of accuracy (against the independent reference, or by Richardson where the error is
 * below the reference's own), the accuracy goal against the reference, exact stops, the same
 * stop at every step size, and determinism.
 */
class ConvergenceTest {

    /** The smooth sine course: h = 0.4 + 0.1 sin(x) cos(0.7 y), mu_k 0.05. */
    private static final World SINE = TestWorlds.world(TestWorlds.sine(), 0.05, 0.1, 20);

    /**
     * The ball's position after exactly one second of rolling on the sine course, played by the
     * engine with this integrator and step: the time limit of 1 s ends the stroke there.
     */
    private static double[] engineAtOneSecond(Integrator integrator, double dt) {
        ShotResult r = new Simulator(SINE, new SimulationSettings(integrator, dt, 1)).simulate(-2, -1, 2.5, 1.5);
        assertEquals(Outcome.TIMEOUT, r.outcome(), "the ball must still be rolling");
        assertEquals(1, r.time(), 1e-12);
        return new double[] {r.endX(), r.endY()};
    }

    /** The same position from the independent reference (minigolf.physics.reference, Dormand-Prince 5(4) at 1e-10). */
    private static double[] referenceAtOneSecond() {
        ReferenceResult r = new ReferenceSimulator(SINE, 1).simulate(-2, -1, 2.5, 1.5);
        assertEquals(Outcome.TIMEOUT, r.outcome());
        return new double[] {r.endX(), r.endY()};
    }

    @ParameterizedTest
    @CsvSource({"EULER, 2", "RK2, 4"})
    void halvingTheFixedStepDividesTheErrorAgainstTheReferenceByTwoToTheOrder(Integrator integrator,
                                                                              double expectedRatio) {
        double[] reference = referenceAtOneSecond();
        double coarse = distance(engineAtOneSecond(integrator, 1.0 / 50), reference);
        double fine = distance(engineAtOneSecond(integrator, 1.0 / 100), reference);
        assertEquals(expectedRatio, coarse / fine, expectedRatio * 0.15, "error " + coarse + " -> " + fine);
    }

    /**
     * RK4 (steps up to dt) and the long steps' fifth-order formula, each at fixed steps: the
     * differences between the ends at h, h/2 and h/4 shrink by 2^order (their errors are far
     * below the reference's own tolerance, so each is measured against itself, by Richardson).
     */
    @ParameterizedTest
    @CsvSource({"1, 0.02, 16", "1e-9, 0.1, 32"})
    void theRk4AndLongStepFormulasConvergeAtTheirOrders(double longFrom, double h, double expectedRatio) {
        double[] a = fixedSteps(longFrom, h), b = fixedSteps(longFrom, h / 2), c = fixedSteps(longFrom, h / 4);
        double ratio = distance(a, b) / distance(b, c);
        assertEquals(expectedRatio, ratio, expectedRatio * 0.15, distance(a, b) + " -> " + distance(b, c));
    }

    /** One second on the sine course in fixed steps of h (steps longer than longFrom are long steps). */
    private static double[] fixedSteps(double longFrom, double h) {
        RollingStep step = new RollingStep(SINE.terrain(), SINE.friction(), null, TestWorlds.G, false, Integrator.RK4, longFrom);
        step.reset();
        double x = -2, y = -1, vx = 2.5, vy = 1.5;
        double[] ground = new double[3];
        for (int i = 0; i < Math.round(1 / h); i++) {
            SINE.terrain().sample(x, y, ground);
            step.acceleration(ground[1], ground[2], 0, 0, 0.05, vx, vy);
            step.from(x, y, vx, vy, ground[1], ground[2], 0.05, 0, 0);
            step.advance(h, RollingStep.Kind.INTEGRATOR, step.ax, step.ay);
            x = step.nx;
            y = step.ny;
            vx = step.nvx;
            vy = step.nvy;
        }
        return new double[] {x, y};
    }

    @Test
    void theGameEndsWithinAMillimetreOfTheReference() {
        World sine = TestWorlds.world(TestWorlds.sine(), 0.08, 0.2, 20);
        Simulator game = TestWorlds.rk4(sine);
        ReferenceSimulator reference = new ReferenceSimulator(sine);
        Random random = new Random(7);
        for (int shot = 0; shot < 8; shot++) {
            double angle = random.nextDouble() * 2 * Math.PI, speed = 1 + 3 * random.nextDouble();
            ShotResult a = game.simulate(0, 0, speed * Math.cos(angle), speed * Math.sin(angle));
            ReferenceResult b = reference.simulate(0, 0, speed * Math.cos(angle), speed * Math.sin(angle));
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
        double[] tinySteps = null;
        for (double dt : new double[] {1e-5, 1e-3, 1.0 / 60}) {
            ShotResult r = new Simulator(lake, SimulationSettings.DEFAULT.withDt(dt))
                    .simulate(-3, 0, -1.053636851465158, 0.02728162072030483);
            assertEquals(Outcome.STOPPED, r.outcome(), "dt " + dt);
            if (tinySteps == null) tinySteps = new double[] {r.endX(), r.endY()};
            assertEquals(0, Math.hypot(r.endX() - tinySteps[0], r.endY() - tinySteps[1]), 1e-5, "dt " + dt);
        }
        assertEquals(3.3322, Math.hypot(tinySteps[0], tinySteps[1]), 1e-4);
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
        ShotResult tinySteps = new Simulator(world, SimulationSettings.DEFAULT.withDt(1e-5))
                .simulate(-4, -3, 0.2719865323628711, -0.7444444263380493);
        assertEquals(Outcome.STOPPED, tinySteps.outcome());
        assertTrue(tinySteps.time() < 3, "stopped after " + tinySteps.time() + " s");
        ShotResult game = TestWorlds.rk4(world).simulate(-4, -3, 0.2719865323628711, -0.7444444263380493);
        assertEquals(0, Math.hypot(game.endX() - tinySteps.endX(), game.endY() - tinySteps.endY()), 5e-3);
    }

    @Test
    void aBallTheControlKeepsAtShortStepsStopsInsteadOfCreeping() throws Exception {
        // Up the lake's rim and back: near its stop the control had halved the steps to dt/8, and
        // looking only that far ahead the stop was never found, so RK4's stages flipped friction
        // and the ball crept at 0.5 mm/s for 407 s (195,257 steps). The stop looks dt/4 ahead.
        World lake = World.load(java.nio.file.Path.of("courses/lake.json"));
        ShotResult r = TestWorlds.rk4(lake).simulate(-3, 0, -1.3979863803917207, -0.12202122564737901);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertTrue(r.time() < 1 && r.steps() < 100, r.time() + " s, " + r.steps() + " steps");
        ReferenceResult reference = new ReferenceSimulator(lake).simulate(-3, 0, -1.3979863803917207, -0.12202122564737901);
        assertEquals(0, Math.hypot(r.endX() - reference.endX(), r.endY() - reference.endY()), 1e-3);
    }
}
