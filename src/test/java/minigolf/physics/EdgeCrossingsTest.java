package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import org.junit.jupiter.api.Test;

/** The push zones' edges found in closed form give StepLocator's bisection's answer bit for bit, with fewer tests. */
class EdgeCrossingsTest {
    private static final PhysicsSettings PHYSICS = new PhysicsSettings(9.81, 0.1, 0.2, 5, PhysicsModel.CLASSIC);
    /** The push zones of courses/windmill-push.json: a funnel of two zones meeting at y = 0, and one further on. */
    private static final ForceField FUNNEL = new ForceField(List.of(
            new PushZone(new Shape.Rect(new Vec2(-2.6, -0.85), new Vec2(-1.2, 0.0)), new Vec2(0, 0.9)),
            new PushZone(new Shape.Rect(new Vec2(-2.6, 0.0), new Vec2(-1.2, 0.85)), new Vec2(0, -0.9)),
            new PushZone(new Shape.Rect(new Vec2(1.0, -0.85), new Vec2(2.4, 0.85)), new Vec2(0.6, 0))), List.of());
    private static final FrictionField NO_ZONES = new FrictionField(PHYSICS, List.of(), new TerrainSpec.HeightExpression("0"));
    private static final double CLOSE = 0.125 * StepLocator.EDGE_CONFIRM;

    /** StepLocator's bisection on the cubic: the reference. */
    private static double bisection(double[] c, StepLocator.PointTest test) {
        double before = 0, after = 1;
        for (int k = 0; k < StepLocator.LOCATE_ITERATIONS && after - before > CLOSE; k++) {
            double mid = 0.5 * (before + after);
            if (test.at(PathSweep.hermite(mid, c[0], c[1], c[2], c[3]), PathSweep.hermite(mid, c[4], c[5], c[6], c[7]))) after = mid;
            else before = mid;
        }
        return after;
    }

    /** Whether (x, y) is under another push than (x0, y0). */
    private static StepLocator.PointTest pastEdge(double x0, double y0, int[] asked) {
        double[] start = new double[2], here = new double[2];
        FUNNEL.push(x0, y0, start);
        return (x, y) -> {
            asked[0]++;
            FUNNEL.push(x, y, here);
            return here[0] != start[0] || here[1] != start[1];
        };
    }

    @Test
    void sameCrossingAsBisectionOnRandomSteps() {
        EdgeCrossings crossings = EdgeCrossings.of(NO_ZONES, FUNNEL);
        assertNotNull(crossings);
        SplittableRandom random = new SplittableRandom(24);
        int compared = 0, exact = 0;
        long askedBisection = 0, askedExact = 0;
        while (compared < 20000) {
            // A step of up to 1/60 s at up to 5 m/s, turning by up to 1 m/s, near the funnel's edges.
            double x0 = random.nextDouble(-2.8, -1.0), y0 = random.nextDouble(-0.2, 0.2);
            if (random.nextInt(4) == 0) y0 = random.nextDouble(-0.9, 0.9);
            double tau = random.nextDouble(1e-4, 1.0 / 60);
            double speed = Math.pow(10, random.nextDouble(-2.5, Math.log10(5))), angle = random.nextDouble(2 * Math.PI);
            double vx0 = speed * Math.cos(angle), vy0 = speed * Math.sin(angle);
            double vx1 = vx0 + random.nextDouble(-1, 1) * Math.min(1, speed), vy1 = vy0 + random.nextDouble(-1, 1) * Math.min(1, speed);
            double x1 = x0 + 0.5 * (vx0 + vx1) * tau, y1 = y0 + 0.5 * (vy0 + vy1) * tau;
            double[] c = {x0, vx0 * tau, x1, vx1 * tau, y0, vy0 * tau, y1, vy1 * tau};
            int[] asked = new int[1];
            StepLocator.PointTest test = pastEdge(x0, y0, asked);
            // As StepLocator: only a step whose end is under another push is located.
            if (!test.at(x1, y1)) continue;
            asked[0] = 0;
            double expected = bisection(c, test);
            askedBisection += asked[0];
            asked[0] = 0;
            double found = crossings.bisect(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], test, CLOSE, StepLocator.LOCATE_ITERATIONS);
            compared++;
            if (Double.isNaN(found)) continue;
            exact++;
            askedExact += asked[0];
            assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(found),
                    () -> "step " + java.util.Arrays.toString(c) + ": bisection " + expected + ", closed form " + found);
        }
        // Nearly every step is located in closed form, with a few tests each instead of 33.
        assertTrue(exact > 19000, "located in closed form: " + exact);
        assertTrue(askedExact < 0.2 * askedBisection, askedExact + " tests against " + askedBisection);
    }

    @Test
    void grazingAnEdgeIsLeftToBisection() {
        EdgeCrossings crossings = EdgeCrossings.of(NO_ZONES, FUNNEL);
        // A path whose y turns at exactly the funnel's middle edge y = 0 (p(s) = -(1 - s)^2 * 0.01 + ... ):
        // ends y0 = -0.01, y1 = -0.01 with tangents -0.04 / +0.04 reach y = 0 only at a touch? Here: the
        // cubic y(s) = -0.01 + 0.04 s - 0.04 s^2 peaks at exactly 0 at s = 0.5.
        double[] c = {-2.0, 0.01, -1.99, 0.01, -0.01, 0.04, -0.01, -0.04};
        assertEquals(0.0, PathSweep.hermite(0.5, c[4], c[5], c[6], c[7]), 1e-18);
        int[] asked = new int[1];
        double found = crossings.bisect(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], pastEdge(-2.0, -0.01, asked), CLOSE, 50);
        assertTrue(Double.isNaN(found), "a graze is not clean: " + found);
    }

    @Test
    void onlyRectangularPushZonesWithoutFrictionZones() {
        ForceField round = new ForceField(List.of(new PushZone(new Shape.Circle(new Vec2(0, 0), 1), new Vec2(1, 0))), List.of());
        assertNull(EdgeCrossings.of(NO_ZONES, round));
        FrictionField zoned = new FrictionField(PHYSICS, List.of(new Zone(new Shape.Rect(new Vec2(0, 0), new Vec2(1, 1)), 0.3, 0.4, null)),
                new TerrainSpec.HeightExpression("0"));
        assertNull(EdgeCrossings.of(zoned, FUNNEL));
        assertNull(EdgeCrossings.of(NO_ZONES, null));
    }
}
