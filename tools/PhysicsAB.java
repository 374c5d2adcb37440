import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.stream.Stream;

/**
 * Times two builds of the engine against each other in one JVM, on the same random shots, by the
 * thread's CPU time and allocated bytes (docs/measurements.md, "Comparing two builds"). Each build is loaded from its
 * installed lib folder in a class loader of its own; rounds alternate A B B A, so a load that
 * changes during the run falls on both alike.
 *
 * <pre>
 * java tools/PhysicsAB.java A_LIB B_LIB ROUNDS SHOTS COURSE...
 * e.g. java tools/PhysicsAB.java /tmp/base/build/install/minigolf/lib build/install/minigolf/lib 4 20000 courses/lake.json
 * </pre>
 * Prints one line per course and round, then the ratio B/A of shots per CPU second (range and median).
 */
public final class PhysicsAB {
    /** One build: World.load and Simulator.simulate through method handles. */
    static final class Build {
        final String name;
        final MethodHandle load, simulate, steps, maxSpeed, startX, startY;
        final Object settings;
        final MethodHandle newSimulator;

        Build(String name, Path lib) throws Exception {
            this.name = name;
            List<URL> urls = new ArrayList<>();
            try (Stream<Path> jars = Files.list(lib)) {
                for (Path jar : (Iterable<Path>) jars::iterator) if (jar.toString().endsWith(".jar")) urls.add(jar.toUri().toURL());
            }
            ClassLoader loader = new URLClassLoader(urls.toArray(new URL[0]), ClassLoader.getPlatformClassLoader());
            MethodHandles.Lookup l = MethodHandles.publicLookup();
            Class<?> world = loader.loadClass("minigolf.physics.World");
            Class<?> simulator = loader.loadClass("minigolf.physics.Simulator");
            Class<?> settingsClass = loader.loadClass("minigolf.physics.SimulationSettings");
            Class<?> result = loader.loadClass("minigolf.physics.ShotResult");
            Class<?> course = loader.loadClass("minigolf.course.Course");
            Class<?> physics = loader.loadClass("minigolf.course.PhysicsSettings");
            load = l.findStatic(world, "load", MethodType.methodType(world, Path.class));
            settings = settingsClass.getField("DEFAULT").get(null);
            newSimulator = l.findConstructor(simulator, MethodType.methodType(void.class, world, settingsClass));
            simulate = l.findVirtual(simulator, "simulate",
                    MethodType.methodType(result, double.class, double.class, double.class, double.class));
            steps = l.findVirtual(result, "steps", MethodType.methodType(int.class));
            MethodHandle physicsOf = l.findVirtual(world, "physics", MethodType.methodType(physics));
            maxSpeed = MethodHandles.filterReturnValue(physicsOf, l.findVirtual(physics, "maxSpeed", MethodType.methodType(double.class)));
            MethodHandle courseOf = l.findVirtual(world, "course", MethodType.methodType(course));
            Object point = course.getMethod("start").getReturnType();
            Class<?> pointClass = (Class<?>) point;
            MethodHandle start = MethodHandles.filterReturnValue(courseOf, l.findVirtual(course, "start", MethodType.methodType(pointClass)));
            startX = MethodHandles.filterReturnValue(start, l.findVirtual(pointClass, "x", MethodType.methodType(double.class)));
            startY = MethodHandles.filterReturnValue(start, l.findVirtual(pointClass, "y", MethodType.methodType(double.class)));
        }
    }

    /** The shots bench-physics draws (minigolf.cli.RandomShots): any direction, 10-100% of maxSpeed. */
    static double[][] shots(long seed, double maxSpeed, int n) {
        SplittableRandom random = new SplittableRandom(seed);
        double[][] out = new double[n][];
        for (int i = 0; i < n; i++) {
            double angle = random.nextDouble() * 2 * Math.PI;
            double speed = maxSpeed * (0.1 + 0.9 * random.nextDouble());
            out[i] = new double[] {speed * Math.cos(angle), speed * Math.sin(angle)};
        }
        return out;
    }

    /** {shots per CPU second, bytes allocated per shot, mean steps}. */
    static double[] time(Build b, Object simulator, double x, double y, double[][] shots) throws Throwable {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long steps = 0;
        long bytes0 = threads.getThreadAllocatedBytes(id);
        long cpu0 = threads.getCurrentThreadCpuTime();
        for (double[] v : shots) steps += (int) b.steps.invoke(b.simulate.invoke(simulator, x, y, v[0], v[1]));
        long cpu = threads.getCurrentThreadCpuTime() - cpu0;
        long bytes = threads.getThreadAllocatedBytes(id) - bytes0;
        return new double[] {shots.length / (cpu / 1e9), (double) bytes / shots.length, (double) steps / shots.length};
    }

    public static void main(String[] args) throws Throwable {
        Build a = new Build("A", Path.of(args[0]));
        Build b = new Build("B", Path.of(args[1]));
        int rounds = Integer.parseInt(args[2]);
        int n = Integer.parseInt(args[3]);
        for (int c = 4; c < args.length; c++) {
            Path course = Path.of(args[c]);
            Build[] builds = {a, b};
            Object[] sims = new Object[2];
            double x = 0, y = 0;
            double[][] shots = null, warm = null;
            for (int k = 0; k < 2; k++) {
                Object world = builds[k].load.invoke(course);
                sims[k] = builds[k].newSimulator.invoke(world, builds[k].settings);
                x = (double) builds[k].startX.invoke(world);
                y = (double) builds[k].startY.invoke(world);
                double max = (double) builds[k].maxSpeed.invoke(world);
                shots = shots(1, max, n);
                warm = shots(2, max, Math.max(2000, n / 2));
            }
            for (int k = 0; k < 2; k++) for (int w = 0; w < 3; w++) time(builds[k], sims[k], x, y, warm);
            List<Double> ratios = new ArrayList<>();
            for (int r = 0; r < rounds; r++) {
                int first = r % 2 == 0 ? 0 : 1;
                double[][] res = new double[2][];
                res[first] = time(builds[first], sims[first], x, y, shots);
                res[1 - first] = time(builds[1 - first], sims[1 - first], x, y, shots);
                ratios.add(res[1][0] / res[0][0]);
                System.out.printf(Locale.ROOT, "%s round %d: A %.0f shots/cpu-s, %.0f B/shot, %.1f steps | B %.0f shots/cpu-s, %.0f B/shot, %.1f steps | B/A %.3f%n",
                        course, r, res[0][0], res[0][1], res[0][2], res[1][0], res[1][1], res[1][2], res[1][0] / res[0][0]);
            }
            ratios.sort(null);
            System.out.printf(Locale.ROOT, "%s: B/A %.3f-%.3f, median %.3f%n", course, ratios.get(0), ratios.get(ratios.size() - 1),
                    ratios.get(ratios.size() / 2));
        }
    }
}
