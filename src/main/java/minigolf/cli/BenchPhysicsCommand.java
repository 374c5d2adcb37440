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
        description = "Simulates N random legal shots from the start on one thread (after a warm-up) and prints shots per "
                + "second of wall time and of the thread's CPU time (shotsPerCpuSecond: the figure to compare on a shared machine).")
final class BenchPhysicsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--shots", paramLabel = "N", description = "Random legal shots to time (default: ${DEFAULT-VALUE}).")
    int shots = 20000;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of the random shots (default: ${DEFAULT-VALUE}).")
    long seed = 1;

    @Override
    public Integer call() {
        if (shots < 1) throw new UserError("--shots: must be at least 1, got " + shots);
        World world = CourseArgument.load(course);
        Simulator simulator = new Simulator(world, SimulationSettings.DEFAULT);
        // Warm-up: let the JIT compile the stroke and the terrain before timing.
        long warmUpEnd = System.nanoTime() + 2_000_000_000L;
        RandomShots warmUp = new RandomShots(seed + 1, world.physics().maxSpeed());
        while (System.nanoTime() < warmUpEnd) run(simulator, world, warmUp.next());
        RandomShots timed = new RandomShots(seed, world.physics().maxSpeed());
        long steps = 0;
        // Thread CPU time too: on a shared machine wall time counts the other jobs' turns.
        java.lang.management.ThreadMXBean threads = java.lang.management.ManagementFactory.getThreadMXBean();
        boolean cpu = threads.isCurrentThreadCpuTimeSupported();
        long cpuStart = cpu ? threads.getCurrentThreadCpuTime() : 0;
        long start = System.nanoTime();
        for (int i = 0; i < shots; i++) steps += run(simulator, world, timed.next()).steps();
        double seconds = (System.nanoTime() - start) / 1e9;
        double cpuSeconds = cpu ? (threads.getCurrentThreadCpuTime() - cpuStart) / 1e9 : Double.NaN;
        ObjectNode out = Json.object();
        out.put("course", world.course().name());
        out.put("shots", shots);
        out.put("shotsPerSecond", Math.round(shots / seconds));
        out.put("meanSteps", Math.round(10.0 * steps / shots) / 10.0);
        out.put("nsPerStep", Math.round(seconds * 1e9 / steps));
        if (cpuSeconds > 0) out.put("shotsPerCpuSecond", Math.round(shots / cpuSeconds));
        spec.commandLine().getOut().println(Json.write(out));
        return 0;
    }

    private static ShotResult run(Simulator simulator, World world, double[] v) {
        return simulator.simulate(world.course().start().x(), world.course().start().y(), v[0], v[1]);
    }
}
