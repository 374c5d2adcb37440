import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import minigolf.bot.BotProgress;
import minigolf.bot.CancellationToken;
import minigolf.bot.TileCourses;
import minigolf.bot.play.Bots;
import minigolf.bot.play.PlayConditions;
import minigolf.bot.play.Playthrough;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * A bot (by default {@code planner-aces}, the planner's full search; budget 1,000,000, at most 10
 * strokes) on generated tile courses, each course played with its sweeps on one thread and on
 * {@code THREADS} (one build, one JVM; the order alternates course by course), timed by wall
 * time and by the process's CPU time (docs/measurements.md, "The planner's sweeps on more threads").
 * Checks that both play the same game (every shot and simulation count).
 *
 * <pre>
 * java -cp MAIN:TEST:LIB/* tools/PlannerThreads.java SEED COUNT [THREADS] [BOT] [FIRST]
 * </pre>
 * Prints per course: strokes, simulations, wall and CPU seconds on 1 and on THREADS threads, then
 * the median wall times, their ratio, and the games that differ (none expected).
 */
public final class PlannerThreads {
    /** {strokes, simulations, wall s, CPU s}; the game's shots in {@code shots}. */
    static double[] play(World world, String bot, int threads, List<String> shots) {
        com.sun.management.OperatingSystemMXBean os =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        long cpu0 = os.getProcessCpuTime(), wall0 = System.nanoTime();
        Playthrough.Result r = Playthrough.play(Bots.create(bot), world, SimulationSettings.DEFAULT, 10, 1_000_000, 1,
                CancellationToken.none(), BotProgress.NONE, PlayConditions.NONE, threads);
        double wall = (System.nanoTime() - wall0) / 1e9, cpu = (os.getProcessCpuTime() - cpu0) / 1e9;
        for (Playthrough.PlayedShot s : r.shots()) {
            shots.add(s.shot().vx() + "," + s.shot().vy() + "," + s.shot().vz() + ":" + s.simulations());
        }
        return new double[] {r.strokes(), r.simulations(), wall, cpu};
    }

    static double median(List<Double> xs) {
        double[] a = xs.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return a.length % 2 == 1 ? a[a.length / 2] : 0.5 * (a[a.length / 2 - 1] + a[a.length / 2]);
    }

    public static void main(String[] args) {
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        String bot = args.length > 3 ? args[3] : "planner-aces";
        int first = args.length > 4 ? Integer.parseInt(args[4]) : 0;
        List<World> worlds = TileCourses.generate(seed, first + count);
        List<Double> wall1 = new ArrayList<>(), wallN = new ArrayList<>(), cpu1 = new ArrayList<>(), cpuN = new ArrayList<>();
        List<Integer> differ = new ArrayList<>();
        System.out.printf(Locale.ROOT, "course strokes simulations wall1 cpu1 wall%d cpu%d ratio%n", threads, threads);
        for (int i = first; i < first + count; i++) {
            List<String> shots1 = new ArrayList<>(), shotsN = new ArrayList<>();
            double[] one, many;
            if (i % 2 == 0) {
                one = play(worlds.get(i), bot, 1, shots1);
                many = play(worlds.get(i), bot, threads, shotsN);
            } else {
                many = play(worlds.get(i), bot, threads, shotsN);
                one = play(worlds.get(i), bot, 1, shots1);
            }
            boolean same = shots1.equals(shotsN) && Arrays.equals(Arrays.copyOf(one, 2), Arrays.copyOf(many, 2));
            if (!same) differ.add(i);
            wall1.add(one[2]);
            wallN.add(many[2]);
            cpu1.add(one[3]);
            cpuN.add(many[3]);
            System.out.printf(Locale.ROOT, "%d %d %d %.2f %.2f %.2f %.2f %.3f%s%n", i, (int) one[0], (long) one[1], one[2], one[3],
                    many[2], many[3], many[2] / one[2], same ? "" : " DIFFERENT: " + shots1 + " vs " + shotsN);
        }
        double m1 = median(wall1), mN = median(wallN);
        System.out.printf(Locale.ROOT, "median wall s: 1 thread %.2f, %d threads %.2f, ratio %.3f; median CPU s %.2f / %.2f; "
                + "load average now %.2f; games that differ: %s%n", m1, threads, mN, mN / m1, median(cpu1), median(cpuN),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), differ);
    }
}
