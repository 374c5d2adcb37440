package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The loft control: an angle tilts the dragged aim up, the speed limit holds for the whole vector. */
class LoftTest {
    @Test
    void zeroLoftIsThePuttItself() {
        double[] v = Loft.velocity(1.3, -0.7, 0, 5);
        assertArrayEquals(new double[]{1.3, -0.7, 0}, v, 0, "bit for bit");
    }

    @Test
    void theAngleTiltsTheVelocityAndKeepsItsLength() {
        double[] v = Loft.velocity(3, 4, 30, 10); // 5 m/s along (0.6, 0.8)
        assertEquals(5 * Math.cos(Math.toRadians(30)) * 0.6, v[0], 1e-12);
        assertEquals(5 * Math.cos(Math.toRadians(30)) * 0.8, v[1], 1e-12);
        assertEquals(2.5, v[2], 1e-12, "5 sin 30");
        assertEquals(5, Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1e-12);
        assertEquals(30, Loft.degreesOf(v[0], v[1], v[2]), 1e-9);
        double[] steep = Loft.velocity(0, -2, 60, 10);
        assertEquals(0, steep[0], 0);
        assertEquals(-1, steep[1], 1e-12, "2 cos 60");
        assertEquals(Math.sqrt(3), steep[2], 1e-12, "2 sin 60");
    }

    @Test
    void theLimitAppliesToTheWholeVector() {
        // An aim of 6 m/s on a 5 m/s course: the chip leaves at 5 m/s in all, not 5 along the ground.
        double[] v = Loft.velocity(6, 0, 45, 5);
        assertEquals(5, Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1e-12);
        assertEquals(v[0], v[2], 1e-12, "45 degrees");
        assertNull(AimModel.checkTyped(v[0], v[1], v[2], 5), "the game accepts it");
        assertNotNull(AimModel.checkTyped(4, 0, 3.1, 5), "|(4, 0, 3.1)| = 5.06 > 5 is refused");
        assertNotNull(AimModel.checkTyped(1, 0, -0.1, 5), "no shot into the ground");
        double[] putt = Loft.velocity(6, 8, 0, 5);
        assertArrayEquals(new double[]{3, 4, 0}, putt, 1e-12, "a putt is capped too");
    }

    @Test
    void stepsStayBetweenPuttAndSixtyDegrees() {
        assertEquals(5, Loft.step(0, 1));
        assertEquals(0, Loft.step(5, -3));
        assertEquals(60, Loft.step(55, 4));
        assertEquals(0, Loft.clamp(-10));
        assertThrows(IllegalArgumentException.class, () -> Loft.velocity(1, 0, 61, 5));
        assertArrayEquals(new double[]{0, 0, 0}, Loft.velocity(0, 0, 30, 5), 0);
        assertEquals("Putt", Loft.describe(0));
        assertEquals("Chip, 35 degrees up", Loft.describe(35));
    }
}
