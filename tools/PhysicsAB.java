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
 * Prints one line per course and round, then the ratio B/A of shots per CPU second (range and median),
 * then each build's ratio of every further course to the first (e.g. windmill-push to the lake),
 * measured round by round: each round times every course with both builds.
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
        int courses = args.length - 4;
        Build[] builds = {a, b};
        Object[][] sims = new Object[courses][2];
        double[] xs = new double[courses], ys = new double[courses];
        double[][][] shots = new double[courses][][];
        for (int c = 0; c < courses; c++) {
            Path course = Path.of(args[4 + c]);
            double[][] warm = null;
            for (int k = 0; k < 2; k++) {
                Object world = builds[k].load.invoke(course);
                sims[c][k] = builds[k].newSimulator.invoke(world, builds[k].settings);
                xs[c] = (double) builds[k].startX.invoke(world);
                ys[c] = (double) builds[k].startY.invoke(world);
                double max = (double) builds[k].maxSpeed.invoke(world);
                shots[c] = shots(1, max, n);
                warm = shots(2, max, Math.max(2000, n / 2));
            }
            for (int k = 0; k < 2; k++) for (int w = 0; w < 3; w++) time(builds[k], sims[c][k], xs[c], ys[c], warm);
        }
        // Each round times every course with both builds, so the courses' ratios to the first
        // (each build's own) are measured in the same minute too.
        double[][][] speed = new double[courses][2][rounds];
        for (int r = 0; r < rounds; r++) {
            for (int c = 0; c < courses; c++) {
                int first = r % 2 == 0 ? 0 : 1;
                double[][] res = new double[2][];
                res[first] = time(builds[first], sims[c][first], xs[c], ys[c], shots[c]);
                res[1 - first] = time(builds[1 - first], sims[c][1 - first], xs[c], ys[c], shots[c]);
                speed[c][0][r] = res[0][0];
                speed[c][1][r] = res[1][0];
                System.out.printf(Locale.ROOT, "%s round %d: A %.0f shots/cpu-s, %.0f B/shot, %.1f steps | B %.0f shots/cpu-s, %.0f B/shot, %.1f steps | B/A %.3f%n",
                        args[4 + c], r, res[0][0], res[0][1], res[0][2], res[1][0], res[1][1], res[1][2], res[1][0] / res[0][0]);
            }
        }
        for (int c = 0; c < courses; c++) {
            double[] ratios = new double[rounds];
            for (int r = 0; r < rounds; r++) ratios[r] = speed[c][1][r] / speed[c][0][r];
            System.out.printf(Locale.ROOT, "%s: B/A %s%n", args[4 + c], summary(ratios));
        }
        for (int c = 1; c < courses; c++) {
            for (int k = 0; k < 2; k++) {
                double[] ratios = new double[rounds];
                for (int r = 0; r < rounds; r++) ratios[r] = speed[c][k][r] / speed[0][k][r];
                System.out.printf(Locale.ROOT, "%s / %s, build %s: %s%n", args[4 + c], args[4], builds[k].name, summary(ratios));
            }
        }
    }

    /** "lowest-highest, median m" of the values. */
    static String summary(double[] values) {
        double[] v = values.clone();
        java.util.Arrays.sort(v);
        return String.format(Locale.ROOT, "%.3f-%.3f, median %.3f", v[0], v[v.length - 1], v[v.length / 2]);
    }
}
