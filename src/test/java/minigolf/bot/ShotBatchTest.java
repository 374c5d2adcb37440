package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * {@link CountingSimulator#simulateInOrder} against the loop of {@link CountingSimulator#simulate}
 * calls it stands for, on a generated tile course (walls, a height grid: shots of very different
 * lengths, so the threads finish out of order): the same results handed on in the same order, the
 * same count, known results and best shot, the same budget failure, with 1, 2 and 4 threads.
 */
class ShotBatchTest {
    private static final World TILE = TileCourses.generate(5150, 26).get(25);
    private static final double X = TILE.course().start().x(), Y = TILE.course().start().y();
    private static final int SHOTS = 240;

    /** Shots all round, 1.5 degrees apart, at speeds cycling from 0.3 to 1 of the maximum. */
    private static List<Shot> shots() {
        double vMax = TILE.physics().maxSpeed();
        List<Shot> shots = new ArrayList<>();
        for (int i = 0; i < SHOTS; i++) shots.add(Shot.polar(Math.toRadians(1.5 * i), vMax * (0.3 + 0.1 * (i % 8))));
        return shots;
    }

    /** A trial: its shot and a listener of its own that counts the path's steps and sums its x. */
    private static final class Trial implements TrajectoryListener {
        final int index;
        final Shot shot;
        int steps;
        double sumX;

        Trial(int index, Shot shot) {
            this.index = index;
            this.shot = shot;
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            steps++;
            sumX += x;
        }
    }

    /** What a run saw, in order: each result and its trial's listener totals. */
    private record Run(List<String> seen, long count, Shot best, Map<Shot, ShotResult> known) {
    }

    private static CountingSimulator simulator(long budget, int threads) {
        CountingSimulator sim = new CountingSimulator(TILE, SimulationSettings.DEFAULT, budget, CancellationToken.none(),
                BotProgress.NONE);
        sim.spreadOver(threads);
        double hx = TILE.hole().position().x(), hy = TILE.hole().position().y();
        sim.beginShot(X, Y, r -> Math.hypot(r.endX() - hx, r.endY() - hy));
        return sim;
    }

    private static String line(Trial t, ShotResult r) {
        return t.index + " " + r.outcome() + " " + r.endX() + " " + r.endY() + " " + r.time() + " " + t.steps + " " + t.sumX;
    }

    /** The loop the batch stands for: bounds before each shot, the stop after it. */
    private static Run sequential(long budget, int goOnUntil, int stopAt) {
        CountingSimulator sim = simulator(budget, 1);
        List<String> seen = new ArrayList<>();
        List<Shot> shots = shots();
        for (int i = 0; i < SHOTS; i++) {
            if (i >= goOnUntil) break;
            Trial t = new Trial(i, shots.get(i));
            ShotResult r = sim.simulate(X, Y, t.shot, t);
            seen.add(line(t, r));
            if (i == stopAt) break;
        }
        return new Run(seen, sim.count(), sim.bestShot(), Map.copyOf(sim.knownResults()));
    }

    private static Run batch(long budget, int goOnUntil, int stopAt, int threads, int[] stoppedAt) {
        CountingSimulator sim = simulator(budget, threads);
        List<String> seen = new ArrayList<>();
        List<Trial> trials = new ArrayList<>();
        List<Shot> shots = shots();
        for (int i = 0; i < SHOTS; i++) trials.add(new Trial(i, shots.get(i)));
        Trial last = sim.simulateInOrder(X, Y, trials, new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Trial t) {
                return t.shot;
            }

            @Override
            public TrajectoryListener listener(Trial t) {
                return t;
            }

            @Override
            public boolean mayGoOn() {
                return seen.size() < goOnUntil;
            }

            @Override
            public boolean stopsAt(Trial t, ShotResult r) {
                seen.add(line(t, r));
                return t.index == stopAt;
            }
        });
        stoppedAt[0] = last == null ? -1 : last.index;
        return new Run(seen, sim.count(), sim.bestShot(), Map.copyOf(sim.knownResults()));
    }

    private static void assertSameRun(Run expected, Run actual, String what) {
        assertEquals(expected.seen(), actual.seen(), what);
        assertEquals(expected.count(), actual.count(), what);
        assertEquals(expected.best(), actual.best(), what);
        assertEquals(expected.known(), actual.known(), what);
    }

    @Test
    void itHandsOnTheSameResultsAsTheLoopWithAnyNumberOfThreads() {
        Run all = sequential(Long.MAX_VALUE, SHOTS, -1);
        Run stopped = sequential(Long.MAX_VALUE, SHOTS, 137);
        Run bounded = sequential(Long.MAX_VALUE, 90, -1);
        assertEquals(SHOTS, all.count());
        assertEquals(138, stopped.count());
        assertEquals(90, bounded.count());
        // The shots differ (lengths, outcomes): the comparison below is not between copies of one shot.
        assertTrue(all.seen().stream().map(s -> s.split(" ")[5]).distinct().count() > 50, "distinct step counts");
        for (int threads : new int[] {1, 2, 4}) {
            int[] at = new int[1];
            assertSameRun(all, batch(Long.MAX_VALUE, SHOTS, -1, threads, at), threads + " threads, all");
            assertEquals(-1, at[0]);
            assertSameRun(stopped, batch(Long.MAX_VALUE, SHOTS, 137, threads, at), threads + " threads, stopped");
            assertEquals(137, at[0]);
            assertSameRun(bounded, batch(Long.MAX_VALUE, 90, -1, threads, at), threads + " threads, bounded");
            assertEquals(-1, at[0]);
        }
    }

    @Test
    void theBudgetRunsOutAtTheSameShot() {
        for (int threads : new int[] {1, 2, 4}) {
            CountingSimulator sim = simulator(50, threads);
            List<Shot> seen = new ArrayList<>();
            assertThrows(BudgetExhaustedException.class, () -> sim.simulateInOrder(X, Y, shots(), CountingSimulator.InOrder.shots((shot, r) -> !seen.add(shot))));
            assertEquals(50, sim.count(), threads + " threads");
            assertEquals(shots().subList(0, 50), seen, threads + " threads");
            assertEquals(sequential(50 + 1, 50, -1).best(), sim.bestShot(), threads + " threads");
        }
    }

    @Test
    void aCancelledTokenStopsItBeforeTheFirstShot() {
        CancellationToken token = new CancellationToken();
        CountingSimulator sim = new CountingSimulator(TILE, SimulationSettings.DEFAULT, 1000, token, BotProgress.NONE);
        sim.spreadOver(2);
        token.cancel();
        assertThrows(BotCancelledException.class, () -> sim.simulateInOrder(X, Y, shots(), CountingSimulator.InOrder.shots((shot, r) -> false)));
        assertEquals(0, sim.count());
    }

    @Test
    void anEmptyBatchAndBadThreadCounts() {
        CountingSimulator sim = simulator(10, 3);
        assertNull(sim.simulateInOrder(X, Y, List.<Shot>of(), CountingSimulator.InOrder.shots((shot, r) -> true)));
        assertEquals(0, sim.count());
        assertEquals(3, sim.threads());
        assertEquals(3, sim.variant(TILE, false).threads(), "variants share the setting");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> sim.spreadOver(0));
        assertEquals("threads must be 1 to 256, got 0", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> sim.spreadOver(257));
        assertEquals(3, sim.threads(), "unchanged by a refused value");
    }
}
