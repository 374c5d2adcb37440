package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The rest rule (docs/course-format.md, "Coming to rest"): continuous in the shot, with the
 * turning speed's closed form checked against a separate numerical solution.
 */
class RestRuleTest {
    private static final double G = TestWorlds.G;

    @Test
    void aNanometrePerSecondSidewaysNoLongerSendsTheBallSixteenMetresBackDown() {
        // Issue 11: on h = 0.15x (mu_k 0.1, mu_s 0.2) the shot (2, 0) stopped uphill and (2, 1e-9) rolled 16 m back down.
        World plane = TestWorlds.world(TestWorlds.plane(0.15, 0, 5), 0.1, 0.2, 20);
        ShotResult straight = TestWorlds.rk4(plane).simulate(-5, 0, 2, 0);
        ShotResult nudged = TestWorlds.rk4(plane).simulate(-5, 0, 2, 1e-9);
        assertEquals(Outcome.STOPPED, nudged.outcome());
        assertEquals(0, Math.hypot(straight.endX() - nudged.endX(), straight.endY() - nudged.endY()), 1e-6);
        // The closed form's own boundary: 0.6 degrees off stops, 1.4 degrees off turns and rolls out.
        assertEquals(Outcome.STOPPED, TestWorlds.rk4(plane).simulate(-5, 0, 2, 0.02).outcome());
        assertEquals(Outcome.OUT, TestWorlds.rk4(plane).simulate(-5, 0, 2, 0.05).outcome());
    }

    @Test
    void theTurningSpeedsClosedFormMatchesANumericalSolutionOfTheSlopeEquations() {
        // Classic model on a uniform slope s along x: a = -g (s, 0) - mu g v/|v|, integrated with
        // tiny explicit steps until the speed stops falling.
        double s = 0.15, mu = 0.1;
        for (double[] v0 : new double[][] {{2, 0.3}, {1.2, 0.05}, {0.5, 0.4}, {3, -0.8}, {0.2, 0.001}}) {
            double vx = v0[0], vy = v0[1], lowest = Math.hypot(vx, vy);
            double dt = 1e-7;
            for (int i = 0; i < 50_000_000; i++) {
                double speed = Math.hypot(vx, vy);
                double ax = -G * s - mu * G * vx / speed, ay = -mu * G * vy / speed;
                if (ax * vx + ay * vy >= 0) break;
                vx += ax * dt;
                vy += ay * dt;
                lowest = Math.min(lowest, Math.hypot(vx, vy));
            }
            double predicted = TurningPoint.minimumSpeed(v0[0], v0[1], s, 0, mu);
            assertEquals(lowest, predicted, 2e-3 * lowest + 1e-6, "v0 = (" + v0[0] + ", " + v0[1] + ")");
        }
        // Straight up the slope the speed reaches 0; straight down it never has a minimum ahead.
        assertEquals(0, TurningPoint.minimumSpeed(2, 0, 0.15, 0, 0.1));
        assertEquals(2, TurningPoint.minimumSpeed(-2, 0, 0.15, 0, 0.1));
        // A heading 1e-300 off straight up does not overflow.
        assertEquals(0, TurningPoint.minimumSpeed(2, 1e-300, 0.15, 0, 0.1), 1e-200);
    }

    @Test
    void perturbingAShotByAMicrometrePerSecondMovesItsRestPointByLessThanAMillimetre() throws Exception {
        // Slopes between mu_k and mu_s (shots mostly uphill, where the rule decides) and curved courses.
        World[] worlds = {
            TestWorlds.world(TestWorlds.plane(0.12, 0, 5), 0.1, 0.2, 20),
            TestWorlds.world(TestWorlds.plane(0.15, 0.03, 5), 0.1, 0.2, 20),
            TestWorlds.world(TestWorlds.plane(0.18, 0, 5), 0.1, 0.2, 20),
            World.load(Path.of("courses/lake.json")),
            World.load(Path.of("courses/sine-hills.json")),
            World.load(Path.of("courses/sine-cross.json")),
        };
        SplittableRandom random = new SplittableRandom(11);
        int compared = 0, splits = 0;
        for (World world : worlds) {
            Simulator sim = TestWorlds.rk4(world);
            double x0 = world.course().start().x(), y0 = world.course().start().y();
            if (world.course().name().equals("test")) x0 = -5;
            double max = world.physics().maxSpeed();
            for (int i = 0; i < 250; i++) {
                double angle = random.nextDouble(-Math.PI / 3, Math.PI / 3) + (i % 3 == 0 ? random.nextDouble(2 * Math.PI) : 0);
                double speed = random.nextDouble(0.3, 1) * max;
                double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
                double dx = random.nextDouble(-1e-6, 1e-6), dy = random.nextDouble(-1e-6, 1e-6);
                double scale = Math.min(1, max / Math.hypot(vx + dx, vy + dy)) * (1 - 1e-9);
                Path2 pathA = new Path2(), pathB = new Path2();
                ShotResult a = sim.simulate(x0, y0, vx * scale, vy * scale, 0, pathA);
                ShotResult b = sim.simulate(x0, y0, (vx + dx) * scale, (vy + dy) * scale, 0, pathB);
                if (genuineSplit(a, b, pathA, pathB)) {
                    splits++;
                    continue;
                }
                compared++;
                double moved = Math.hypot(a.endX() - b.endX(), a.endY() - b.endY());
                assertTrue(moved < 1e-3, world.course().name() + " shot (" + vx + ", " + vy + "): " + a.outcome()
                        + " moved " + moved + " m by (" + dx + ", " + dy + ")");
            }
        }
        assertTrue(splits * 50 < compared, splits + " splits among " + compared);
    }

    /**
     * The trajectory really forks at an edge: one ball ends in the water, out or in the hole right
     * where the other one passed (a water edge, the bounds, the hole's rim), or the two meet
     * obstacles differently (an obstacle's edge). A ball that stops mid-slope while the other
     * rolls away to end elsewhere is no such fork: the old rest rule's jump is not excused.
     */
    private static boolean genuineSplit(ShotResult a, ShotResult b, Path2 pathA, Path2 pathB) {
        if (a.outcome() != b.outcome()) {
            return a.outcome() != Outcome.STOPPED && pathB.passesWithin(a.endX(), a.endY(), 1e-3)
                    || b.outcome() != Outcome.STOPPED && pathA.passesWithin(b.endX(), b.endY(), 1e-3);
        }
        if (a.events().size() != b.events().size()) return true;
        for (int i = 0; i < a.events().size(); i++) {
            if (a.events().get(i).type() != b.events().get(i).type()) return true;
        }
        return false;
    }

    /** The polyline of a ball's states. */
    private static final class Path2 implements TrajectoryListener {
        private final java.util.List<double[]> points = new java.util.ArrayList<>();

        public void onStep(double t, double x, double y, double vx, double vy) {
        }

        public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
            points.add(new double[] {x, y});
        }

        boolean passesWithin(double px, double py, double tolerance) {
            for (int i = 1; i < points.size(); i++) {
                double[] p = points.get(i - 1), q = points.get(i);
                double ex = q[0] - p[0], ey = q[1] - p[1], length = ex * ex + ey * ey;
                double f = length == 0 ? 0 : Math.max(0, Math.min(1, ((px - p[0]) * ex + (py - p[1]) * ey) / length));
                if (Math.hypot(p[0] + f * ex - px, p[1] + f * ey - py) <= tolerance) return true;
            }
            return false;
        }
    }

    @Test
    void aTerrainThatIsNotFiniteWhereTheBallGoesIsAnErrorNotANaN() throws Exception {
        String json = new String(java.nio.file.Files.readAllBytes(Path.of("courses/flat.json")))
                .replace("\"height\": \"0.1\"", "\"height\": \"sqrt(abs(x - 0.1) - 0.01) + 1\"");
        World world = World.parse(json, "nan.json");
        NonFiniteMotionException e = assertThrows(NonFiniteMotionException.class,
                () -> TestWorlds.rk4(world).simulate(-3, 0, 4, 0));
        assertTrue(e.getMessage().contains("at (0.1"), e.getMessage());
    }
}
