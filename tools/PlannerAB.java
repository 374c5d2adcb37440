import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

/**
 * A bot (by default {@code planner-aces}, the planner's full search; budget 1,000,000, at most 10
 * strokes) on generated tile courses, two builds in one JVM (class loaders of their own), course
 * by course A then B (B then A on odd courses), timed by the thread's CPU time
 * (docs/measurements.md, "Comparing two builds"). Each build is given as its main classes, test
 * classes (TileCourses) and lib folder.
 *
 * <pre>
 * java tools/PlannerAB.java A_MAIN:A_TEST:A_LIB B_MAIN:B_TEST:B_LIB SEED COUNT [BOT]
 * </pre>
 * Prints per course: strokes, simulations and CPU seconds of each, then the medians and the
 * strokes that differ.
 */
public final class PlannerAB {
    static final class Build {
        final MethodHandle generate, create, play, strokes, simulations, holed;
        final Object settings, progress;
        final MethodHandle token;

        Build(String spec) throws Exception {
            String[] parts = spec.split(":");
            List<URL> urls = new ArrayList<>();
            urls.add(Path.of(parts[0]).toUri().toURL());
            urls.add(Path.of(parts[1]).toUri().toURL());
            try (Stream<Path> jars = Files.list(Path.of(parts[2]))) {
                for (Path jar : (Iterable<Path>) jars::iterator) {
                    if (jar.toString().endsWith(".jar") && !jar.getFileName().toString().startsWith("minigolf")) {
                        urls.add(jar.toUri().toURL());
                    }
                }
            }
            ClassLoader loader = new URLClassLoader(urls.toArray(new URL[0]), ClassLoader.getPlatformClassLoader());
            MethodHandles.Lookup l = MethodHandles.publicLookup();
            Class<?> world = loader.loadClass("minigolf.physics.World");
            Class<?> tiles = loader.loadClass("minigolf.bot.TileCourses");
            Class<?> bot = loader.loadClass("minigolf.bot.Bot");
            Class<?> bots = load(loader, "minigolf.bot.play.Bots", "minigolf.bot.Bots");
            Class<?> playthrough = load(loader, "minigolf.bot.play.Playthrough", "minigolf.bot.Playthrough");
            Class<?> result = loader.loadClass(playthrough.getName() + "$Result");
            Class<?> settingsClass = loader.loadClass("minigolf.physics.SimulationSettings");
            Class<?> tokenClass = loader.loadClass("minigolf.bot.CancellationToken");
            Class<?> progressClass = loader.loadClass("minigolf.bot.BotProgress");
            generate = l.findStatic(tiles, "generate", MethodType.methodType(List.class, long.class, int.class));
            create = l.findStatic(bots, "create", MethodType.methodType(bot, String.class));
            play = l.findStatic(playthrough, "play", MethodType.methodType(result, bot, world, settingsClass, int.class,
                    long.class, long.class, tokenClass, progressClass));
            strokes = l.findVirtual(result, "strokes", MethodType.methodType(int.class));
            simulations = l.findVirtual(result, "simulations", MethodType.methodType(long.class));
            holed = l.findVirtual(result, "holed", MethodType.methodType(boolean.class));
            settings = settingsClass.getField("DEFAULT").get(null);
            progress = progressClass.getField("NONE").get(null);
            token = l.findStatic(tokenClass, "withTimeLimit", MethodType.methodType(tokenClass, double.class));
        }

        private static Class<?> load(ClassLoader loader, String name, String old) throws ClassNotFoundException {
            try {
                return loader.loadClass(name);
            } catch (ClassNotFoundException e) {
                return loader.loadClass(old);
            }
        }

        /** {strokes, simulations, CPU seconds, holed (1/0)}. */
        double[] play(Object world, String bot) throws Throwable {
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            long cpu = threads.getCurrentThreadCpuTime();
            // A time limit far beyond any course's: the result must not depend on the machine's load.
            Object r = play.invoke(create.invoke(bot), world, settings, 10, 1_000_000L, 1L, token.invoke(3600.0), progress);
            double seconds = (threads.getCurrentThreadCpuTime() - cpu) / 1e9;
            return new double[] {(int) strokes.invoke(r), (long) simulations.invoke(r), seconds, (boolean) holed.invoke(r) ? 1 : 0};
        }
    }

    public static void main(String[] args) throws Throwable {
        Build a = new Build(args[0]), b = new Build(args[1]);
        long seed = Long.parseLong(args[2]);
        int count = Integer.parseInt(args[3]);
        String bot = args.length > 4 ? args[4] : "planner-aces";
        List<?> wa = (List<?>) a.generate.invoke(seed, count), wb = (List<?>) b.generate.invoke(seed, count);
        double[] ta = new double[count], tb = new double[count];
        int same = 0;
        List<String> differ = new ArrayList<>();
        System.out.println("| course | A strokes | A simulations | A CPU s | B strokes | B simulations | B CPU s | B/A |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|");
        for (int i = 0; i < count; i++) {
            double[] ra, rb;
            if (i % 2 == 0) {
                ra = a.play(wa.get(i), bot);
                rb = b.play(wb.get(i), bot);
            } else {
                rb = b.play(wb.get(i), bot);
                ra = a.play(wa.get(i), bot);
            }
            ta[i] = ra[2];
            tb[i] = rb[2];
            if (ra[0] == rb[0] && ra[3] == rb[3]) same++; else differ.add(seed + "-" + i + ": " + (int) ra[0] + " -> " + (int) rb[0]);
            System.out.printf(Locale.ROOT, "| %d-%d | %d%s | %,d | %.2f | %d%s | %,d | %.2f | %.2f |%n", seed, i, (int) ra[0],
                    ra[3] == 1 ? "" : " (not holed)", (long) ra[1], ra[2], (int) rb[0], rb[3] == 1 ? "" : " (not holed)",
                    (long) rb[1], rb[2], rb[2] / ra[2]);
        }
        Arrays.sort(ta);
        Arrays.sort(tb);
        System.out.printf(Locale.ROOT, "median CPU s per course: A %.2f, B %.2f (B/A %.2f); same strokes on %d of %d%s%n",
                median(ta), median(tb), median(tb) / median(ta), same, count, differ.isEmpty() ? "" : ": differ " + differ);
    }

    private static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }
}
