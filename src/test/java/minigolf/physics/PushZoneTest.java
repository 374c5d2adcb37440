package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** Push zones (docs/course-format.md, "Push zones"): a constant force that acts as a tilt of the ground. */
class PushZoneTest {
    static final double G = 9.81;
    static final String EVERYWHERE = "\"pushZones\": [{\"shape\": {\"type\": \"rect\", \"min\": [-5, -5], \"max\": [5, 5]}, \"push\": [%s, %s]}]";

    @Test
    void aBallPushedBackStopsWhereTheClosedFormSays() {
        // Flat ground, push +1 m/s^2 along x, a shot straight against it: it decelerates at
        // mu_k g + 1 and stops after v^2 / (2 (mu_k g + 1)); the pull (0.102) is below mu_s (0.3),
        // so it stays there.
        World w = ElementWorlds.flat(String.format(EVERYWHERE, 1, 0));
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, -2, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        double a = 0.1 * G + 1;
        assertEquals(-4 / (2 * a), r.endX(), 2e-5);
        assertEquals(2 / a, r.time(), 1e-3);
    }

    @Test
    void aPushIsTheSameAsATilt() {
        // The classic model: flat ground with push f rolls exactly as the plane h = -f.x/g does.
        // Both take long steps (inside a zone that holds the whole step the push is constant:
        // docs/physics.md, "Step control"); they agree to a micrometre, not to the last bit.
        World pushed = ElementWorlds.flat(String.format(EVERYWHERE, 0.6, -0.3));
        World tilted = ElementWorlds.course("1-" + (0.6 / G) + "*x+" + (0.3 / G) + "*y", "");
        Random random = new Random(24);
        for (int i = 0; i < 40; i++) {
            double speed = 0.5 + 2.5 * random.nextDouble(), angle = 2 * Math.PI * random.nextDouble();
            double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
            ShotResult a = ElementWorlds.simulator(pushed).simulate(0, 0, vx, vy);
            ShotResult b = ElementWorlds.simulator(tilted).simulate(0, 0, vx, vy);
            assertEquals(b.outcome(), a.outcome());
            assertEquals(b.endX(), a.endX(), 1e-6, "shot " + i);
            assertEquals(b.endY(), a.endY(), 1e-6, "shot " + i);
        }
    }

    @Test
    void aBallStaysOnlyWhereStaticFrictionHoldsAgainstSlopePlusPush() {
        // Shot against the push, the ball stops in the zone. A push of 1.5 m/s^2 (0.153 in slope
        // units) on the slope 0.11 that pulls the same way, 0.263 in all, is held by mu_s 0.3; a push
        // of 2 (0.314 in all) is not: the ball rolls back out of the zone and down the slope.
        String zone = "\"pushZones\": [{\"shape\": {\"type\": \"rect\", \"min\": [-1, -1], \"max\": [1, 1]}, \"push\": [%s, 0]}]";
        ShotResult held = ElementWorlds.simulator(ElementWorlds.course("1-0.11*x", String.format(zone, 1.5))).simulate(0, 0, -0.5, 0);
        assertEquals(Outcome.STOPPED, held.outcome());
        double a = 0.11 * G + 1.5 + 0.1 * G;
        assertEquals(-0.25 / (2 * a), held.endX(), 2e-5);
        ShotResult rolls = ElementWorlds.simulator(ElementWorlds.course("1-0.11*x", String.format(zone, 2))).simulate(0, 0, -0.5, 0);
        assertEquals(Outcome.OUT, rolls.outcome());
        assertEquals(5, rolls.endX(), 1e-6);
    }

    @Test
    void stepsEndAtAPushZonesEdge() {
        // A ball rolling across the edge of a push zone that pushes it back: the energy it has at
        // the edge is its own, so it gets exactly v0^2/(2 mu_k g) - ... : on flat ground before the
        // edge at x = 1 it loses mu_k g per metre; past it (mu_k g + f) per metre.
        String zone = "\"pushZones\": [{\"shape\": {\"type\": \"rect\", \"min\": [1, -5], \"max\": [5, 5]}, \"push\": [-1.5, 0]}]";
        double v0 = 2.5, muG = 0.1 * G;
        double atEdge = v0 * v0 - 2 * muG * 1;
        double expected = 1 + atEdge / (2 * (muG + 1.5));
        ShotResult r = ElementWorlds.simulator(ElementWorlds.flat(zone)).simulate(0, 0, v0, 0);
        assertEquals(expected, r.endX(), 1e-5);
    }
}
