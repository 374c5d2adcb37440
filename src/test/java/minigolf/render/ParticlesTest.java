package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The effects' particles, headless: bursts, flight, the end of the effect. */
class ParticlesTest {
    @Test
    void confettiRisesFlutersDownAndEnds() {
        Particles p = new Particles();
        assertFalse(p.isActive());
        assertNull(p.mesh());
        p.burst(Particles.Kind.CONFETTI, 1, 2, 0.1, 7);
        assertEquals(70, p.count());
        assertEquals(70 * 2, p.mesh().triangleCount(), "two triangles per square");
        double top = 0;
        for (int i = 0; i < 30; i++) {
            p.update(1 / 60.0);
            top = Math.max(top, p.top());
        }
        // Launched at 1.2 to 2 m/s against 0.6 g: up to 2^2 / (2 * 0.6 * 9.81) = 0.34 m.
        assertTrue(top > 0.1 + 0.15 && top < 0.1 + 0.36, "top " + top);
        for (int i = 0; i < 60 * 3 && p.isActive(); i++) p.update(1 / 60.0);
        assertFalse(p.isActive(), "the confetti is gone within its life (2.2 s)");
        assertNull(p.mesh());
    }

    @Test
    void aHoleInOneIsABiggerHigherLongerBurst() {
        Particles normal = new Particles(), ace = new Particles();
        normal.burst(Particles.Kind.CONFETTI, 0, 0, 0, 3);
        ace.burst(Particles.Kind.ACE_CONFETTI, 0, 0, 0, 3);
        assertTrue(ace.count() > 2 * normal.count(), ace.count() + " vs " + normal.count());
        double topNormal = 0, topAce = 0;
        int framesNormal = 0, framesAce = 0;
        for (int i = 0; i < 60 * 5; i++) {
            normal.update(1 / 60.0);
            ace.update(1 / 60.0);
            if (normal.isActive()) framesNormal++;
            if (ace.isActive()) framesAce++;
            topNormal = Math.max(topNormal, normal.isActive() ? normal.top() : 0);
            topAce = Math.max(topAce, ace.isActive() ? ace.top() : 0);
        }
        assertTrue(topAce > topNormal, topAce + " vs " + topNormal);
        assertTrue(framesAce > framesNormal, framesAce + " vs " + framesNormal);
        assertFalse(ace.isActive());
    }

    @Test
    void aSplashFallsBackIntoTheWaterAndBurstsAreDeterministic() {
        Particles a = new Particles(), b = new Particles();
        a.burst(Particles.Kind.SPLASH, 0.5, 0.5, 0, 42);
        b.burst(Particles.Kind.SPLASH, 0.5, 0.5, 0, 42);
        assertArrayEquals(a.mesh().vertices(), b.mesh().vertices(), "the same seed, the same splash");
        int frames = 0;
        while (a.isActive() && frames < 600) {
            a.update(1 / 60.0);
            frames++;
        }
        // Up at 0.96 to 1.6 m/s under full gravity: back under the surface within 2 * 1.6 / 9.81 = 0.33 s.
        assertTrue(frames <= 21, "frames " + frames);
    }

    @Test
    void theClockStartsOnTheFirstCall() {
        Particles p = new Particles();
        p.burst(Particles.Kind.CONFETTI, 0, 0, 0, 1);
        p.advanceTo(100); // sets the clock only
        assertEquals(70, p.count());
        p.advanceTo(100.5);
        assertTrue(p.isActive());
        assertEquals(70, p.count(), "a long frame moves it at most 0.1 s");
        for (int i = 1; i <= 240; i++) p.advanceTo(100.5 + i / 60.0);
        assertFalse(p.isActive(), "over after its life, whatever the clock's origin");
    }
}
