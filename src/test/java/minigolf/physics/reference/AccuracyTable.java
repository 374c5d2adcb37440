package minigolf.physics.reference;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * The accuracy table of docs/physics-accuracy.md (as {@code bench-accuracy COURSE --shots N}, seed 1,
 * for every course at once) with the independent reference's results kept in a file, so that an
 * engine change is checked against the same reference runs in seconds instead of an hour:
 *
 * <pre>
 * CP='build/classes/java/test:build/classes/java/main:build/resources/main:build/install/minigolf/lib/*'
 * java -cp "$CP" minigolf.physics.reference.AccuracyTable reference /tmp/ref.txt 1000 courses/*.json courses/bench/*.json courses/holes/*.json
 * java -cp "$CP" minigolf.physics.reference.AccuracyTable engine /tmp/ref.txt
 * </pre>
 * The first writes, per course and shot, the shot, the reference's end and outcome and whether it
 * is ill-conditioned ({@link Conditioning}); the second runs the engine (RK4, the default step) on
 * the same shots and prints per course: within 1 mm, compared, ill-conditioned, median, p99.9 and
 * worst error, the worst shot, and the total.
 */
public final class AccuracyTable {
    private AccuracyTable() {
    }

    public static void main(String[] args) throws Exception {
        if (args[0].equals("reference")) {
            writeReference(Paths.get(args[1]), Integer.parseInt(args[2]), Arrays.copyOfRange(args, 3, args.length));
        } else {
            compare(Paths.get(args[1]));
        }
    }

    /** The shots bench-accuracy draws (minigolf.cli.RandomShots, seed 1). */
    static double[][] shots(double maxSpeed, int n) {
        SplittableRandom random = new SplittableRandom(1);
        double[][] out = new double[n][];
        for (int i = 0; i < n; i++) {
            double angle = random.nextDouble() * 2 * Math.PI;
            double speed = maxSpeed * (0.1 + 0.9 * random.nextDouble());
            out[i] = new double[] {speed * Math.cos(angle), speed * Math.sin(angle)};
        }
        return out;
    }

    private static void writeReference(Path out, int n, String[] courses) throws Exception {
        try (PrintWriter w = new PrintWriter(Files.newBufferedWriter(out))) {
            for (String course : courses) {
                World world = World.load(Paths.get(course));
                ReferenceSimulator reference = new ReferenceSimulator(world);
                double x0 = world.course().start().x(), y0 = world.course().start().y();
                double[][] shots = shots(world.physics().maxSpeed(), n);
                for (int i = 0; i < n; i++) {
                    double[] v = shots[i];
                    ReferenceResult b = reference.simulate(x0, y0, v[0], v[1]);
                    if (!b.covered()) {
                        w.printf(Locale.ROOT, "%s %d %s %s not-covered%n", course, i, hex(v[0]), hex(v[1]));
                        continue;
                    }
                    boolean ill = Conditioning.illConditioned(Conditioning.spread(reference, x0, y0, v[0], v[1], b));
                    w.printf(Locale.ROOT, "%s %d %s %s %s %s %s %s%n", course, i, hex(v[0]), hex(v[1]),
                            b.outcome().jsonName(), hex(b.endX()), hex(b.endY()), ill ? "ill" : "ok");
                }
                w.flush();
                System.err.println(course);
            }
        }
    }

    private static void compare(Path referenceFile) throws Exception {
        List<String> lines = Files.readAllLines(referenceFile);
        String course = null;
        List<Double> errors = new ArrayList<>();
        int[] totals = new int[2];
        Simulator engine = null;
        double x0 = 0, y0 = 0;
        int ill = 0;
        String worst = "";
        double worstError = -1;
        for (int k = 0; k <= lines.size(); k++) {
            String[] f = k < lines.size() ? lines.get(k).split(" ") : null;
            if (f == null || !f[0].equals(course)) {
                if (course != null) {
                    report(course, errors, ill, worst, totals);
                }
                if (f == null) break;
                course = f[0];
                World world = World.load(Paths.get(course));
                engine = new Simulator(world, SimulationSettings.DEFAULT);
                x0 = world.course().start().x();
                y0 = world.course().start().y();
                errors.clear();
                ill = 0;
                worst = "";
                worstError = -1;
            }
            if (f[4].equals("not-covered")) continue;
            if (f[7].equals("ill")) {
                ill++;
                continue;
            }
            double vx = unhex(f[2]), vy = unhex(f[3]);
            ShotResult a = engine.simulate(x0, y0, vx, vy);
            double error = Math.hypot(a.endX() - unhex(f[5]), a.endY() - unhex(f[6]));
            errors.add(error);
            if (error > worstError) {
                worstError = error;
                worst = String.format(Locale.ROOT, "#%s %s/%s", f[1], a.outcome().jsonName(), f[4]);
            }
        }
        System.out.printf(Locale.ROOT, "total: %d of %d within 1 mm (%.3f%%)%n", totals[0], totals[1],
                100.0 * totals[0] / totals[1]);
    }

    private static void report(String course, List<Double> errors, int ill, String worst, int[] totals) {
        double[] e = errors.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        int within = 0;
        for (double d : e) if (d <= 1e-3) within++;
        totals[0] += within;
        totals[1] += e.length;
        System.out.printf(Locale.ROOT, "| `%s` | %d | %d | %d | %s | %s | %s | %s%n", course, within, e.length, ill,
                micrometres(rank(e, 0.5)), micrometres(rank(e, 0.999)), micrometres(rank(e, 1)), worst);
    }

    private static double rank(double[] sorted, double fraction) {
        if (sorted.length == 0) return Double.NaN;
        int r = (int) Math.ceil(fraction * sorted.length);
        return sorted[Math.max(0, Math.min(sorted.length - 1, r - 1))];
    }

    private static String micrometres(double metres) {
        double um = metres * 1e6;
        if (um < 1e-4) return "< 0.0001 µm";
        if (um >= 1000) return String.format(Locale.ROOT, "%.2g mm", um / 1000);
        return String.format(Locale.ROOT, "%.2g µm", um);
    }

    private static String hex(double d) {
        return Long.toHexString(Double.doubleToRawLongBits(d));
    }

    private static double unhex(String s) {
        return Double.longBitsToDouble(Long.parseUnsignedLong(s, 16));
    }
}
