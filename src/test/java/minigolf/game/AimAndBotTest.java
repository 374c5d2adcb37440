package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CancellationException;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

class AimAndBotTest {
    @Test
    void pullBackAimsTheOtherWayAndCapsTheSpeed() {
        assertArrayEquals(new double[]{2, 0}, AimModel.velocityForPull(0, 0, -1, 0, 4, 2), 1e-12, "half pull, half power");
        assertArrayEquals(new double[]{0, -4}, AimModel.velocityForPull(1, 1, 1, 9, 4, 2), 1e-12, "over-pull is capped");
        assertArrayEquals(new double[]{0, 0}, AimModel.velocityForPull(1, 1, 1, 1, 4, 2), 0);
        assertNull(AimModel.checkTyped(3, 4, 5));
        assertEquals("5.000 m/s is faster than the course's maximum 4.000 m/s", AimModel.checkTyped(3, 4, 4));
        assertEquals("the velocity is zero", AimModel.checkTyped(0, 0, 4));
    }

    /** The closed-form putt on flat ground, found by the same kind of search a bot does: simulate and bisect on speed. */
    static final class BisectingPlanner implements ShotPlanner {
        public String name() {
            return "bisect";
        }

        public double[] plan(World world, SimulationSettings settings, double x, double y, int n, long seed, Control control) {
            double hx = world.hole().position().x() - x, hy = world.hole().position().y() - y, d = Math.hypot(hx, hy);
            var sim = new minigolf.physics.Simulator(world, settings);
            double lo = 0, hi = world.physics().maxSpeed();
            for (int i = 0; i < 40; i++) {
                if (control.isCancelled()) throw new CancellationException();
                double mid = 0.5 * (lo + hi);
                var r = sim.simulate(x, y, hx / d * mid, hy / d * mid);
                if (r.outcome() == Outcome.HOLED) return new double[]{hx / d * mid, hy / d * mid};
                if (Math.hypot(r.endX() - x, r.endY() - y) < d) lo = mid; else hi = mid;
                control.progress(i / 40.0, "simulated " + (i + 1) + " shots");
            }
            return new double[]{hx / d * hi, hy / d * hi};
        }
    }

    @Test
    void aBotPlaysItsTurnOnAWorkerThread() throws Exception {
        Game g = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.bot("Robo", "bisect")), 10);
        PlayerState s = g.player(0);
        BotTurn turn = new BotTurn(new BisectingPlanner(), g.world(), g.settings(), s.x(), s.y(), 0, 1L);
        turn.join(10_000);
        assertTrue(turn.isDone());
        assertNull(turn.failure());
        assertEquals(Outcome.HOLED, g.play(turn.shot()[0], turn.shot()[1]).outcome());
        assertEquals(Math.sqrt(2 * GameTest.MU_G * Math.hypot(6, 0.5)), Math.hypot(turn.shot()[0], turn.shot()[1]), 0.01);
    }

    @Test
    void aBotCanBeCancelledAndATooFastShotIsCapped() throws Exception {
        ShotPlanner forever = new ShotPlanner() {
            public String name() {
                return "forever";
            }

            public double[] plan(World w, SimulationSettings s, double x, double y, int n, long seed, Control c) {
                while (!c.isCancelled()) Thread.onSpinWait();
                throw new CancellationException();
            }
        };
        BotTurn turn = new BotTurn(forever, GameTest.FLAT, SimulationSettings.DEFAULT, -3, 0, 0, 1L);
        assertTrue(!turn.isDone());
        turn.cancel();
        turn.join(5_000);
        assertTrue(turn.isDone());
        assertEquals("cancelled", turn.failure());
        assertNull(turn.shot());

        ShotPlanner greedy = new ShotPlanner() {
            public String name() {
                return "greedy";
            }

            public double[] plan(World w, SimulationSettings s, double x, double y, int n, long seed, Control c) {
                return new double[]{30, 40};
            }
        };
        BotTurn capped = new BotTurn(greedy, GameTest.FLAT, SimulationSettings.DEFAULT, -3, 0, 0, 1L);
        capped.join(5_000);
        assertArrayEquals(new double[]{2.4, 3.2, 0}, capped.shot(), 1e-12, "scaled to maxSpeed 4 (vz 0: a putt)");
    }
}
