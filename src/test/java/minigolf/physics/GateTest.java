package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** One-way gates (docs/course-format.md, "One-way gates"): crossed towards their passTo side only. */
class GateTest {
    // A gate across the course at x = 1, passing to its right: +x (from (1, -5) looking towards (1, 5)).
    static final World GATE = ElementWorlds.flat("\"obstacles\": [{\"type\": \"gate\", \"from\": [1, -5], \"to\": [1, 5], "
            + "\"height\": 0.1, \"passTo\": \"right\", \"restitution\": 0.5}]");

    @Test
    void theBallPassesTowardsThePassSide() {
        ShotResult r = ElementWorlds.simulator(GATE).simulate(0, 0, 2.5, 0, 0, null);
        assertEquals(2.5 * 2.5 / (2 * 0.981), r.endX(), 2e-5);
        assertTrue(r.events().stream().noneMatch(e -> e.type() == StrokeEvent.Type.COLLISION));
    }

    @Test
    void theBallBouncesOffFromThePassSide() {
        // From x = 2 leftwards: it meets the face a ball radius short of x = 1 and keeps half its speed.
        ShotResult r = ElementWorlds.simulator(GATE).simulate(2, 0.5, -2.5, 0, 0, null);
        double contact = 1 + GATE.physics().ballRadius(), mg = 0.981;
        double v1 = Math.sqrt(6.25 - 2 * mg * (2 - contact));
        assertEquals(contact + 0.25 * v1 * v1 / (2 * mg), r.endX(), 2e-5);
        assertEquals(StrokeEvent.Type.COLLISION, r.events().get(0).type());
        assertEquals(contact, r.events().get(0).x(), 1e-6);
    }

    @Test
    void noShotEverEndsOnTheWrongSideFromThePassSide() {
        // Every shot from the pass side, in every direction, at up to maxSpeed: the ball never gets
        // past the gate's line with its centre (the gate spans the whole course).
        Random random = new Random(2424);
        Simulator sim = ElementWorlds.simulator(GATE);
        for (int i = 0; i < 300; i++) {
            double angle = 2 * Math.PI * random.nextDouble(), speed = 5 * random.nextDouble();
            ShotResult r = sim.simulate(1.3, -2 + 4 * random.nextDouble(), speed * Math.cos(angle), speed * Math.sin(angle));
            assertTrue(r.endX() > 1, "shot " + i + " ended at " + r.endX());
        }
    }
}
