package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Bumpers: restitution above 1, with the cap of docs/course-format.md ("Bumpers"). */
class BumperTest {
    @Test
    void aBumperMultipliesTheNormalSpeedByItsRestitution() {
        Bounce b = new Bounce(5);
        b.off(-2, 0, 0, 1, 0, 0, 1.5, 0, 0, 0);
        assertEquals(3, b.vx, 1e-15);
        // A glancing hit keeps its tangential speed.
        b.off(-1, 2, 0, 1, 0, 0, 1.5, 0, 0, 0);
        assertEquals(1.5, b.vx, 1e-15);
        assertEquals(2, b.vy, 1e-15);
    }

    @Test
    void theSpeedAfterABumperIsCappedAtMaxSpeed() {
        Bounce b = new Bounce(5);
        b.off(-4, 0, 0, 1, 0, 0, 1.5, 0, 0, 0); // 6 m/s would be too fast
        assertEquals(5, b.vx, 1e-15);
        b.off(-3, 4, 0, 1, 0, 0, 2, 0, 0, 0); // tangential 4 kept, normal up to 3 (|v| = 5)
        assertEquals(3, b.vx, 1e-12);
        assertEquals(4, b.vy, 1e-15);
        // A ball already faster than maxSpeed keeps its speed, as off a restitution of 1.
        b.off(-6, 0, 0, 1, 0, 0, 1.5, 0, 0, 0);
        assertEquals(6, b.vx, 1e-15);
    }

    @Test
    void aBallRollingIntoABumperComesBackFaster() {
        // Flat ground, mu_k g = 0.981: the ball reaches the bumper (centre 1.5, radius 0.1) at
        // v1 = sqrt(v0^2 - 2 mu g d), leaves at 1.5 v1 and rolls back (1.5 v1)^2 / (2 mu g).
        World w = ElementWorlds.flat("\"obstacles\": [{\"type\": \"bumper\", \"position\": [1.5, 0], \"radius\": 0.1}]");
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, 2, 0, 0, null);
        double contact = 1.5 - 0.1 - w.physics().ballRadius();
        double mg = 0.1 * 9.81;
        double v1 = Math.sqrt(4 - 2 * mg * contact);
        assertEquals(contact - 2.25 * v1 * v1 / (2 * mg), r.endX(), 1e-4);
        assertEquals(List.of(StrokeEvent.Type.COLLISION, StrokeEvent.Type.STOP),
                r.events().stream().map(StrokeEvent::type).toList());
        assertEquals(1.5, r.events().get(0).speedAfter() / r.events().get(0).speedBefore(), 1e-9);
    }
}
