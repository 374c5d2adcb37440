package minigolf.cli;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "bench-physics",
        description = "Simulates N random legal shots from the start (after a warm-up) on one thread or several and prints "
                + "shots per second of wall time and of the threads' CPU time (shotsPerCpuSecond: the figure to compare on "
                + "a shared machine), bytes allocated a shot and a checksum of every shot's result (the same for any "
                + "number of threads).")
final class BenchPhysicsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--shots", paramLabel = "N", description = "Random legal shots to time (default: ${DEFAULT-VALUE}).")
    int shots = 20000;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of the random shots (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Option(names = "--threads", paramLabel = "N",
            description = "Threads sharing the shots, each with its own simulator; the results are the same for any "
                    + "number (compare 'checksum') (default: ${DEFAULT-VALUE}).")
    int threads = 1;

    @Override
    public Integer call() throws InterruptedException {
        if (shots < 1) throw new UserError("--shots: must be at least 1, got " + shots);
        if (threads < 1 || threads > 256) throw new UserError("--threads: must be 1 to 256, got " + threads);
        World world = CourseArgument.load(course);
        RandomShots timed = new RandomShots(seed, world.physics().maxSpeed());
        double[][] velocities = new double[shots][];
        for (int i = 0; i < shots; i++) velocities[i] = timed.next();
        ShotResult[] results = new ShotResult[shots];
        Worker[] workers = new Worker[threads];
        for (int k = 0; k < threads; k++) workers[k] = new Worker(world, velocities, results, k, threads);
        // Warm-up (2 s, all threads at once): let the JIT compile the stroke and the terrain before timing.
        long warmUpEnd = System.nanoTime() + 2_000_000_000L;
        runAll(workers, w -> w.warmUp(warmUpEnd));
        long start = System.nanoTime();
        runAll(workers, Worker::time);
        double seconds = (System.nanoTime() - start) / 1e9;
        long steps = 0, cpuNanos = 0, bytes = 0;
        boolean cpu = true;
        for (Worker w : workers) {
            cpuNanos += w.cpuNanos;
            bytes += w.bytes;
            cpu &= w.cpuNanos >= 0;
        }
        long checksum = 0x9E3779B97F4A7C15L;
        for (ShotResult r : results) {
            steps += r.steps();
            for (long bits : new long[] {r.outcome().ordinal(), Double.doubleToLongBits(r.endX()),
                    Double.doubleToLongBits(r.endY()), Double.doubleToLongBits(r.time())}) {
                checksum = (checksum ^ bits) * 0xBF58476D1CE4E5B9L;
                checksum ^= checksum >>> 31;
            }
        }
        ObjectNode out = Json.object();
        out.put("course", world.course().name());
        out.put("shots", shots);
        out.put("shotsPerSecond", Math.round(shots / seconds));
        out.put("meanSteps", Math.round(10.0 * steps / shots) / 10.0);
        out.put("nsPerStep", Math.round(seconds * 1e9 * threads / steps));
        if (cpu && cpuNanos > 0) out.put("shotsPerCpuSecond", Math.round(shots / (cpuNanos / 1e9)));
        out.put("threads", threads);
        if (bytes >= 0) out.put("bytesPerShot", Math.round((double) bytes / shots));
        out.put("checksum", String.format("%016x", checksum));
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    /** Runs a task on every worker, each on a thread of its own (the calling one for a single worker). */
    private static void runAll(Worker[] workers, java.util.function.Consumer<Worker> task) throws InterruptedException {
        if (workers.length == 1) {
            task.accept(workers[0]);
            return;
        }
        Thread[] running = new Thread[workers.length];
        RuntimeException[] failed = new RuntimeException[workers.length];
        for (int k = 0; k < workers.length; k++) {
            Worker w = workers[k];
            int index = k;
            running[k] = new Thread(() -> {
                try {
                    task.accept(w);
                } catch (RuntimeException e) {
                    failed[index] = e;
                }
            }, "bench-physics-" + k);
            running[k].start();
        }
        for (Thread t : running) t.join();
        // A thread's failure (terrain that is not finite, ...) is the command's, as on one thread.
        for (RuntimeException e : failed) if (e != null) throw e;
    }

    /**
     * One thread's share of the shots, every threads-th from its first, on a simulator of its own;
     * its thread's CPU time and allocated bytes (-1 where the JVM does not measure them).
     */
    private static final class Worker {
        private final World world;
        private final Simulator simulator;
        private final double[][] velocities;
        private final ShotResult[] results;
        private final int first, stride;
        long cpuNanos = -1, bytes = -1;

        Worker(World world, double[][] velocities, ShotResult[] results, int first, int stride) {
            this.world = world;
            this.simulator = new Simulator(world, SimulationSettings.DEFAULT);
            this.velocities = velocities;
            this.results = results;
            this.first = first;
            this.stride = stride;
        }

        void warmUp(long until) {
            RandomShots warmUp = new RandomShots(first + 1_000_003L, world.physics().maxSpeed());
            int k = 0;
            while (System.nanoTime() < until) run(warmUp.next(), clockOf(k++));
        }

        void time() {
            // Thread CPU time: on a shared machine wall time counts the other jobs' turns.
            java.lang.management.ThreadMXBean bean = java.lang.management.ManagementFactory.getThreadMXBean();
            com.sun.management.ThreadMXBean sun = bean instanceof com.sun.management.ThreadMXBean b ? b : null;
            long id = Thread.currentThread().getId();
            boolean cpu = bean.isCurrentThreadCpuTimeSupported();
            long cpuStart = cpu ? bean.getCurrentThreadCpuTime() : 0;
            long bytesStart = sun != null ? sun.getThreadAllocatedBytes(id) : -1;
            for (int i = first; i < velocities.length; i += stride) results[i] = run(velocities[i], clockOf(i));
            if (cpu) cpuNanos = bean.getCurrentThreadCpuTime() - cpuStart;
            if (sun != null && bytesStart >= 0) bytes = sun.getThreadAllocatedBytes(id) - bytesStart;
        }

        /**
         * Shot i's course clock where obstacles move: spread evenly over 60 s (the golden ratio's
         * sequence), so the shots meet the moving obstacles at every phase; 0 elsewhere.
         */
        private double clockOf(int i) {
            return world.moving() == null ? 0 : 60 * ((i * 0.6180339887498949) % 1.0);
        }

        private ShotResult run(double[] v, double clock) {
            double x = world.course().start().x(), y = world.course().start().y();
            return clock == 0 ? simulator.simulate(x, y, v[0], v[1]) : simulator.simulateAt(clock, x, y, v[0], v[1], 0);
        }
    }
}
