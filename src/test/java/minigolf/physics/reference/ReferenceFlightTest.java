package minigolf.physics.reference;

import static minigolf.physics.reference.ReferenceWorlds.G;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.physics.Outcome;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Flight without drag has closed forms: parabolas, bounces by the documented impact rule, then rolling. */
class ReferenceFlightTest {
    private static ReferenceResult chip(World world, double x0, double vx, double vz) {
        ReferenceResult r = new ReferenceSimulator(world).simulate(x0, 0, vx, 0, vz);
        assertTrue(r.covered(), r.note());
        return r;
    }

    /**
     * A chip on flat ground with restitution 0.5: each flight lasts 2·vz/g; each landing keeps
     * e·vn upwards and takes min(0.4·(1 + e)·vn, 2/7·vt) off the speed along the ground; below a
     * 1 mm hop the ball settles and rolls vt²/(2μk·g) further.
     */
    @Test
    void aChipBouncesBySteadyRulesAndRollsOut() {
        double e = 0.5, mu = 0.1, hop = Math.sqrt(2 * G * 1e-3);
        World flat = ReferenceWorlds.flightWorld(ReferenceWorlds.plane(0, 0.1), mu, 20, 0, e);
        ReferenceResult r = chip(flat, -15, 3, 2);
        double x = -15, t = 0, vx = 3, vz = 2;
        while (true) {
            double flight = 2 * vz / G;
            x += vx * flight;
            t += flight;
            vx -= Math.min(0.4 * (1 + e) * vz, vx * 2 / 7);
            if (e * vz < hop) break;
            vz *= e;
        }
        x += vx * vx / (2 * mu * G);
        t += vx / (mu * G);
        assertEquals(Outcome.STOPPED, r.outcome());
        assertEquals(x, r.endX(), 1e-8);
        assertEquals(0, r.endY(), 1e-12);
        assertEquals(t, r.time(), 1e-8);
    }

    /**
     * On the crest h = c − a·x²/2 a ball at its top with v² > g/a has vᵀHv = −a·v² &lt; −g: it takes
     * off at once and, without drag, follows z = c − g·x²/(2v²), always above the ground, until it
     * comes down on the water's surface (z = 0) at x = v·√(2c/g).
     */
    @Test
    void aFastBallTakesOffAtACrestAndFallsIntoTheWater() {
        double a = 2, c = 1, v = 3;
        World crest = ReferenceWorlds.flightWorld(ReferenceWorlds.crest(a, c), 0.1, 20, 0, null);
        ReferenceResult r = chip(crest, 0, v, 0);
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(v * Math.sqrt(2 * c / G), r.endX(), 1e-9);
        assertEquals(Math.sqrt(2 * c / G), r.time(), 1e-9);
    }
}
