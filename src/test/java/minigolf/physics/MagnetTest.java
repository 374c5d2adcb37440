package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.Magnet;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** Magnets (docs/course-format.md, "Magnets"): an attracting or repelling point force within a radius. */
class MagnetTest {
    @Test
    void theForceIsMinusTheGradientOfThePotentialAndPeaksAtAThird() {
        ForceField f = new ForceField(List.of(), List.of(new Magnet(new Vec2(1, -1), 0.9, 2.5)));
        double[] out = new double[2];
        double h = 1e-6;
        for (double[] p : new double[][] {{1.2, -1.1}, {0.5, -0.6}, {1.05, -1.0}, {1.7, -1.4}}) {
            f.force(p[0], p[1], out);
            double gx = (f.magnetPotential(p[0] + h, p[1]) - f.magnetPotential(p[0] - h, p[1])) / (2 * h);
            double gy = (f.magnetPotential(p[0], p[1] + h) - f.magnetPotential(p[0], p[1] - h)) / (2 * h);
            assertEquals(-gx, out[0], 1e-7);
            assertEquals(-gy, out[1], 1e-7);
        }
        f.force(1 + 0.3, -1, out); // R/3 from the centre: |f| = strength, towards the centre
        assertEquals(-2.5, out[0], 1e-12);
        assertEquals(0, out[1], 1e-12);
        f.force(1 + 0.9, -1, out); // at the rim and beyond: nothing
        assertEquals(0, out[0], 1e-15);
        assertEquals(0.9 * 2.5 * 9 / 16, f.magnetPotential(5, 5), 1e-12);
    }

    @Test
    void anAttractingMagnetHoldsTheBallNearItsCentre() {
        // Released 0.25 m from an attracting magnet on flat ground, the ball rolls in and comes to
        // rest where static friction holds against the pull: within (27/4) s u (1-u)^2 <= mu_s g.
        World w = ElementWorlds.flat("\"magnets\": [{\"position\": [0.25, 0], \"radius\": 0.6, \"strength\": 3}]");
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, 0, 0.2);
        assertEquals(Outcome.STOPPED, r.outcome());
        double u = Math.hypot(r.endX() - 0.25, r.endY()) / 0.6;
        assertTrue(Magnet.profile(u) * 3 <= 0.3 * 9.81 + 1e-9, "held: u = " + u);
        assertTrue(u < 0.2, "near the centre: " + u);
    }

    @Test
    void aRepellingMagnetStopsABallWhereItsEnergyRunsOut() {
        // Straight at a repelling magnet (s = -4 m/s^2, R = 0.5 m, centre x = 1) on flat ground:
        // the ball stops where v0^2/2 = mu_k g x + U(x) - U(outside), and stays (pull below mu_s).
        World w = ElementWorlds.flat("\"magnets\": [{\"position\": [1, 0], \"radius\": 0.5, \"strength\": -4}]");
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, 1.2, 0);
        assertEquals(Outcome.STOPPED, r.outcome());
        double lo = 0, hi = 1;
        for (int k = 0; k < 60; k++) {
            double x = 0.5 * (lo + hi), u = Math.min(1, (1 - x) / 0.5);
            double potential = -4 * 0.5 * 6.75 * (u * u / 2 - 2 * u * u * u / 3 + u * u * u * u / 4);
            double spent = 0.1 * 9.81 * x + potential - (-4 * 0.5 * 9 / 16.0);
            if (spent < 0.72) lo = x; else hi = x;
        }
        assertEquals(lo, r.endX(), 2e-5);
        assertTrue(r.endX() < 1.44 / (2 * 0.981) - 0.05, "short of where it would stop without the magnet");
    }
}
