package minigolf.game;

import minigolf.app.GameLauncher;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The aim guide: the real engine's stroke, in a window or, as the game shows it, whole until it
 * stops, drops or leaves play, capped at FULL_SECONDS (flat course: h = 0.1, mu_k = 0.1; lake).
 */
class AimGuideTest {
    static final World FLAT = GameLauncher.loadBundled("/courses/flat.json");
    static final double MU_G = 0.1 * 9.81;

    @Test
    void onFlatGroundItEndsWhereTheBallIsAfterOneSecond() {
        // 2 m/s along +x: after 1 s the ball has rolled 2 - mu g / 2 = 1.50950 m and is still moving.
        AimGuide g = AimGuide.preview(FLAT, SimulationSettings.DEFAULT, -3, 0, 2, 0, AimGuide.SECONDS);
        assertNull(g.outcome(), "the stroke goes on past the guide");
        float[] p = g.points();
        assertEquals(-3, p[0], 1e-6);
        assertEquals(0, p[1], 1e-6);
        assertEquals(0.1, p[2], 1e-6, "contact point on the ground");
        int last = 3 * (g.pointCount() - 1);
        assertEquals(-3 + 2 - MU_G / 2, p[last], 1e-4);
        assertEquals(0, p[last + 1], 1e-6);
        assertEquals(61, g.pointCount(), "the start and one point per 1/60 s frame");
        for (int i = 3; i < p.length; i += 3) assertTrue(p[i] > p[i - 3], "forward all the way");
    }

    @Test
    void aSoftShotEndsAtItsRestPoint() {
        // 1 m/s stops after v^2 / (2 mu g) = 0.5097 m, in 1.019 s: just past the window, so 0.9 m/s (0.918 s).
        double v = 0.9;
        AimGuide g = AimGuide.preview(FLAT, SimulationSettings.DEFAULT, -3, 0, 0, v, AimGuide.SECONDS);
        assertEquals(Outcome.STOPPED, g.outcome());
        int last = 3 * (g.pointCount() - 1);
        assertEquals(v * v / (2 * MU_G), g.points()[last + 1], 1e-4);
    }

    @Test
    void outOfBoundsEndsTheGuideAtTheEdge() {
        // The flat course's edge is 1 m behind the start.
        AimGuide g = AimGuide.preview(FLAT, SimulationSettings.DEFAULT, -3, 0, -3, 0, AimGuide.SECONDS);
        assertEquals(Outcome.OUT, g.outcome());
        assertEquals(-4, g.points()[3 * (g.pointCount() - 1)], 0.06);
    }

    @Test
    void itIsThePlayedStrokeCutAtOneSecond() {
        World lake = GameLauncher.loadBundled("/courses/lake.json");
        SimulationSettings s = SimulationSettings.DEFAULT;
        AimGuide g = AimGuide.preview(lake, s, -3, 0, 3.1, 0.4, AimGuide.SECONDS);
        List<double[]> played = new ArrayList<>();
        played.add(new double[]{0, -3, 0});
        new Simulator(lake, s).simulate(-3, 0, 3.1, 0.4, new TrajectoryListener() {
            @Override
            public void onStep(double t, double x, double y, double vx, double vy) {
            }

            @Override
            public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
                played.add(new double[]{t, x, y});
            }
        });
        assertEquals(Outcome.WATER, g.outcome());
        assertTrue(g.pointCount() > 30, g.pointCount() + " points: one per frame until the ball reaches the water");
        // Each frame's point lies on the played path between the steps around its time (steps are
        // longer than frames where the path is easy: a step's chord strays from the path by far
        // less than a millimetre).
        double end = played.get(played.size() - 1)[0];
        for (int k = 1; k < g.pointCount(); k++) {
            double t = k * s.dt();
            if (t > end) {
                // Past the stroke's end the guide ends where the ball went into the water.
                assertEquals(g.pointCount() - 1, k, "the end is the last point");
                assertEquals((float) played.get(played.size() - 1)[1], g.points()[3 * k], 1e-6);
                break;
            }
            int i = 0;
            while (i + 2 < played.size() && played.get(i + 1)[0] < t) i++;
            double[] a = played.get(i), b = played.get(i + 1);
            double px = g.points()[3 * k], py = g.points()[3 * k + 1];
            double dx = b[1] - a[1], dy = b[2] - a[2];
            double off = Math.abs((px - a[1]) * dy - (py - a[2]) * dx) / Math.hypot(dx, dy);
            assertTrue(off < 1e-3, "frame " + k + " is " + off + " m off the path");
            assertTrue(a[0] <= t + 1e-9 && t <= b[0] + 1e-9, "frame " + k + " between the steps at " + a[0] + " and " + b[0]);
        }
    }

    @Test
    void theSettingIsKeptAndDefaultsToOn() {
        assertTrue(UserSettings.DEFAULTS.aimGuide());
        assertFalse(UserSettings.DEFAULTS.withAimGuide(false).aimGuide());
        assertFalse(UserSettings.DEFAULTS.withAimGuide(false).withMouseSpeed(2).aimGuide(), "other changes keep it");
    }

    @Test
    void theGamesGuideShowsTheWholePuttToItsRestPoint() {
        // 3 m/s along +x stops after v^2 / (2 mu g) = 4.5872 m, in v / (mu g) = 3.058 s: three times the old window.
        AimGuide g = AimGuide.preview(FLAT, SimulationSettings.DEFAULT, -3, 0, 3, 0, AimGuide.FULL_SECONDS);
        assertEquals(Outcome.STOPPED, g.outcome());
        int last = 3 * (g.pointCount() - 1);
        assertEquals(-3 + 9 / (2 * MU_G), g.points()[last], 1e-4);
        assertTrue(g.pointCount() > 3 * 60, "more than three seconds of steps: " + g.pointCount());
        // Towards the cup (3, 0.5) at the pace that reaches it: the guide ends in the hole.
        double dx = 6, dy = 0.5, d = Math.hypot(dx, dy), v = Math.sqrt(2 * MU_G * d);
        assertEquals(Outcome.HOLED, AimGuide.preview(FLAT, SimulationSettings.DEFAULT, -3, 0, v * dx / d, v * dy / d,
                AimGuide.FULL_SECONDS).outcome(), "the guide shows the putt dropping");
    }

    @Test
    void aBallCirclingAConeIsCutAtTheCap() throws Exception {
        // On the cone (slope 1) a ball spirals in for up to 19 s of motion and more: the guide stops at the cap.
        World cone = World.load(java.nio.file.Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "hostile",
                "cone.json"));
        var start = cone.course().start();
        AimGuide g = AimGuide.preview(cone, SimulationSettings.DEFAULT, start.x(), start.y(), 0, 4, 1.0);
        assertNull(g.outcome(), "still rolling after one second");
        AimGuide full = AimGuide.preview(cone, SimulationSettings.DEFAULT, start.x(), start.y(), 0, 4, AimGuide.FULL_SECONDS);
        assertTrue(full.pointCount() <= AimGuide.FULL_SECONDS * 60 * 2 + 2, "bounded by the cap: " + full.pointCount());
    }

    @Test
    void theWorkerHandsOutTheWholeGuideWithoutWaiting() throws Exception {
        try (AimGuideWorker worker = new AimGuideWorker()) {
            SimulationSettings s = SimulationSettings.DEFAULT;
            assertNull(worker.guide(FLAT, s, -3, 0, 3, 0, 0, 0), "nothing is ready at the first ask: it is worked out meanwhile");
            for (int i = 0; i < 500 && !worker.isReady(FLAT, -3, 0, 3, 0, 0, 0, s); i++) Thread.sleep(10);
            AimGuide g = worker.guide(FLAT, s, -3, 0, 3, 0, 0, 0);
            assertArrayEquals(AimGuide.preview(FLAT, s, -3, 0, 3, 0, AimGuide.FULL_SECONDS).points(), g.points());
            // A new aim: the last guide stays on show (the same array) until the new one is ready.
            assertSame(g, worker.guide(FLAT, s, -3, 0, 2, 0, 0, 0));
            for (int i = 0; i < 500 && !worker.isReady(FLAT, -3, 0, 2, 0, 0, 0, s); i++) Thread.sleep(10);
            assertEquals(-3 + 4 / (2 * MU_G), worker.guide(FLAT, s, -3, 0, 2, 0, 0, 0).points()[3 * (worker.guide(FLAT, s, -3, 0, 2,
                    0, 0, 0).pointCount() - 1)], 1e-4);
        }
    }
}
