package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The ball slides to the cup's centre and sinks below the green, then is gone. */
class CupDropTest {
    @Test
    void theBallSlidesToTheCentreSinksAndEnds() {
        CupDrop d = new CupDrop();
        assertNull(d.view(), "nothing before a drop");
        d.start(1.04, 0, 1, 0, 0.1, 0.02, new float[]{1, 0.5f, 0});
        d.advanceTo(10.0);
        BallView first = d.view();
        assertEquals(1.04, first.x(), 1e-6);
        assertEquals(0.1, first.z(), 1e-6, "it starts on the ground");
        d.advanceTo(10.0 + CupDrop.DURATION / 2);
        BallView half = d.view();
        assertEquals(1.0, half.x(), 1e-6, "at the centre after half the drop");
        // s = 1/2: 2.5 r s^2 = 0.0125 m below the ground
        assertEquals(0.1 - 2.5 * 0.02 * 0.25, half.z(), 1e-6);
        assertEquals(1f, half.red());
        d.advanceTo(10.0 + CupDrop.DURATION * 0.99);
        assertTrue(d.view().z() < 0.1 - 2 * 0.02, "two radii down: out of sight below the green");
        d.advanceTo(10.0 + CupDrop.DURATION + 0.01);
        assertFalse(d.isActive());
        assertNull(d.view());
    }
}
