package minigolf.bot;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import minigolf.physics.ShotResult;
import minigolf.physics.Simulator;
import minigolf.physics.TrajectoryListener;

/**
 * One {@link CountingSimulator#simulateInOrder}: the trials' shots are taken in order by the
 * caller's thread and up to {@code threads - 1} helpers (each on an engine of its own), and the
 * caller goes through the results in order, counting and handing on each as a loop of
 * {@link CountingSimulator#simulate} calls would. A sweep that stops early has simulated at most
 * the shots already taken by then; those are not counted, so counts and choices do not depend on
 * the number of threads or on which thread ran which shot.
 */
final class ShotBatch<T> {
    /** Helper threads, shared by every game in the process; daemons, so they never keep it alive. */
    private static final ExecutorService POOL = Executors.newCachedThreadPool(task -> {
        Thread t = new Thread(task, "bot-sweep");
        t.setDaemon(true);
        return t;
    });

    private final CountingSimulator sim;
    private final double x, y;
    private final List<T> trials;
    private final CountingSimulator.InOrder<T> order;
    private final Shot[] shots;
    private final TrajectoryListener[] listeners;
    private final ShotResult[] results;
    private final Throwable[] failures;
    /** Guarded by {@code this}: which trials have run (their result or failure is in place). */
    private final boolean[] done;
    /** The next trial no thread has taken yet. */
    private final AtomicInteger next = new AtomicInteger();
    /** Set when the caller is through: helpers take no more trials. */
    private volatile boolean over;

    ShotBatch(CountingSimulator sim, double x, double y, List<T> trials, CountingSimulator.InOrder<T> order) {
        this.sim = sim;
        this.x = x;
        this.y = y;
        this.trials = trials;
        this.order = order;
        int n = trials.size();
        shots = new Shot[n];
        listeners = new TrajectoryListener[n];
        results = new ShotResult[n];
        failures = new Throwable[n];
        done = new boolean[n];
        for (int i = 0; i < n; i++) {
            shots[i] = sim.limit(order.shot(trials.get(i)));
            listeners[i] = order.listener(trials.get(i));
        }
    }

    T run() {
        int n = trials.size();
        int helpers = Math.min(sim.threads() - 1, n - 1);
        CountDownLatch finished = new CountDownLatch(Math.max(helpers, 0));
        for (int k = 1; k <= helpers; k++) {
            Simulator engine = sim.helper(k);
            POOL.execute(() -> {
                try {
                    work(engine, sim.newWatchdog());
                } finally {
                    finished.countDown();
                }
            });
        }
        Simulator own = sim.engine();
        CountingSimulator.Watchdog watchdog = sim.newWatchdog();
        try {
            for (int i = 0; i < n; i++) {
                if (!order.mayGoOn()) return null;
                sim.token().throwIfCancelled();
                awaitOrRun(i, own, watchdog);
                sim.charge();
                rethrow(failures[i]);
                if (!sim.later(shots[i])) sim.remember(x, y, shots[i], results[i]);
                if (order.stopsAt(trials.get(i), results[i])) return trials.get(i);
            }
            return null;
        } finally {
            over = true;
            awaitHelpers(finished);
        }
    }

    /** A helper: takes the next trial until none is left or the caller is through. */
    private void work(Simulator engine, CountingSimulator.Watchdog watchdog) {
        while (!over) {
            int j = next.getAndIncrement();
            if (j >= shots.length) return;
            runTrial(j, engine, watchdog);
        }
    }

    /** Until trial i has run, the caller takes trials itself; when every trial is taken, it waits for i. */
    private void awaitOrRun(int i, Simulator own, CountingSimulator.Watchdog watchdog) {
        while (!isDone(i)) {
            int j = next.getAndIncrement();
            if (j < shots.length) {
                runTrial(j, own, watchdog);
            } else {
                waitFor(i);
            }
        }
    }

    private void runTrial(int j, Simulator engine, CountingSimulator.Watchdog watchdog) {
        ShotResult r = null;
        Throwable failure = null;
        try {
            r = sim.run(engine, watchdog, x, y, shots[j], listeners[j]);
        } catch (RuntimeException | Error e) {
            // Handed on when the caller reaches this trial (a trial past a stop never is).
            failure = e;
        }
        synchronized (this) {
            results[j] = r;
            failures[j] = failure;
            done[j] = true;
            notifyAll();
        }
    }

    private synchronized boolean isDone(int i) {
        return done[i];
    }

    private synchronized void waitFor(int i) {
        boolean interrupted = false;
        while (!done[i]) {
            try {
                wait();
            } catch (InterruptedException e) {
                // A bot is stopped by its token, which the running shot checks; keep the flag for the caller.
                interrupted = true;
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
    }

    private static void awaitHelpers(CountDownLatch finished) {
        boolean interrupted = false;
        while (true) {
            try {
                finished.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
    }

    private static void rethrow(Throwable failure) {
        if (failure instanceof RuntimeException e) throw e;
        if (failure instanceof Error e) throw e;
    }
}
