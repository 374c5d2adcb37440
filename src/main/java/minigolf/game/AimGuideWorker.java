package minigolf.game;

import java.util.Arrays;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Works out the aim guide off the render thread: the render thread asks for the guide of the aim
 * it shows and gets at once the newest guide worked out so far (for that aim, or the one before
 * while the new one is on its way); one daemon thread simulates the latest aim asked for and
 * skips those the player has already moved past. Each guide is the whole putt until it stops,
 * drops or leaves play, capped at {@link AimGuide#FULL_SECONDS} of the ball's motion.
 */
public final class AimGuideWorker implements AutoCloseable {
    private record Request(World world, SimulationSettings settings, double[] key) {
    }

    private final Object lock = new Object();
    private final Thread thread;
    private Request wanted;
    private double[] doneKey;
    private World doneWorld;
    private AimGuide done;
    private boolean closed;

    public AimGuideWorker() {
        thread = new Thread(this::run, "aim-guide");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * The guide for a stroke (vx, vy, vz) from (x, y) hit at course clock {@code clock}: the one for
     * exactly this aim and moment when it is ready, else the newest one ready on the same course
     * (null before the first). Never waits. Where nothing moves the clock is left out of the key, so
     * a still aim is worked out once; where obstacles move, each new moment is worked out afresh.
     */
    public AimGuide guide(World world, SimulationSettings settings, double x, double y, double vx, double vy, double vz,
                          double clock) {
        double[] key = key(world, settings, x, y, vx, vy, vz, clock);
        synchronized (lock) {
            boolean ready = done != null && doneWorld == world && Arrays.equals(key, doneKey);
            if (!ready && (wanted == null || wanted.world() != world || !Arrays.equals(key, wanted.key()))) {
                wanted = new Request(world, settings, key);
                lock.notifyAll();
            }
            return doneWorld == world ? done : null;
        }
    }

    /** Whether the guide for this aim is ready (tests). */
    public boolean isReady(World world, double x, double y, double vx, double vy, double vz, double clock,
                           SimulationSettings settings) {
        double[] key = key(world, settings, x, y, vx, vy, vz, clock);
        synchronized (lock) {
            return done != null && doneWorld == world && Arrays.equals(key, doneKey);
        }
    }

    private static double[] key(World world, SimulationSettings settings, double x, double y, double vx, double vy,
                                double vz, double clock) {
        return new double[]{x, y, vx, vy, vz, world.moving() != null ? clock : 0, settings.dt(),
                settings.integrator().ordinal()};
    }

    private void run() {
        while (true) {
            Request r;
            synchronized (lock) {
                while (wanted == null && !closed) {
                    try {
                        lock.wait();
                    } catch (InterruptedException e) {
                        return;
                    }
                }
                if (closed) return;
                r = wanted;
                wanted = null;
            }
            double[] k = r.key();
            AimGuide g = AimGuide.preview(r.world(), r.settings(), k[0], k[1], k[2], k[3], k[4], k[5], AimGuide.FULL_SECONDS);
            synchronized (lock) {
                done = g;
                doneKey = k;
                doneWorld = r.world();
            }
        }
    }

    @Override
    public void close() {
        synchronized (lock) {
            closed = true;
            lock.notifyAll();
        }
    }
}
