package minigolf.physics;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Records the exact results of seeded random shots on every course under a folder, so that a
 * refactoring of the engine can be checked bit for bit: run it before and after and {@code diff}
 * the two files. Each line is one shot: course, kind, outcome, steps, event count, then end point,
 * end height and time as the hex of their raw bits, and a hash of every state and event the
 * listener saw (so the whole trajectory, not only its end, must match).
 *
 * <p>Per course: N putts, N chips and N putts aimed near the hole from the start and N from 0.2 to 2 m off it (RK4, the default step), and N/5 putts each with RK2 and
 * Euler (the uncontrolled integrators). Shots as {@code bench-physics} draws them: any direction,
 * 10% to 100% of maxSpeed; a chip rises at 5 to 60 degrees. Files that are not courses are
 * skipped. Use (after {@code gradle --no-daemon -q installDist testClasses}):
 *
 * <pre>
 * java -cp 'build/classes/java/test:build/classes/java/main:build/resources/main:build/install/minigolf/lib/*' \
 *     minigolf.physics.StrokeRecorder courses 60 /tmp/stroke-before.txt
 * </pre>
 */
public final class StrokeRecorder {
    private StrokeRecorder() {
    }

    public static void main(String[] args) throws IOException {
        Path root = Paths.get(args.length > 0 ? args[0] : "courses");
        int n = args.length > 1 ? Integer.parseInt(args[1]) : 60;
        Path out = Paths.get(args.length > 2 ? args[2] : "/tmp/strokes.txt");
        List<Path> files;
        try (Stream<Path> walk = Files.walk(root)) {
            files = walk.filter(p -> p.toString().endsWith(".json")).sorted().collect(Collectors.toList());
        }
        int shots = 0, courses = 0;
        try (PrintWriter w = new PrintWriter(Files.newBufferedWriter(out))) {
            for (Path file : files) {
                World world;
                try {
                    world = World.load(file);
                } catch (Exception e) {
                    continue; // a round file, not a course
                }
                courses++;
                String name = root.relativize(file).toString();
                long seed = name.hashCode();
                shots += record(w, name, world, SimulationSettings.DEFAULT, "putt", n, seed, false);
                shots += record(w, name, world, SimulationSettings.DEFAULT, "chip", n, seed + 1, true);
                shots += record(w, name, world, SimulationSettings.DEFAULT, "aim", n, seed + 4, false);
                shots += record(w, name, world, SimulationSettings.DEFAULT, "near", n, seed + 5, false);
                shots += record(w, name, world, SimulationSettings.DEFAULT.withIntegrator(Integrator.RK2),
                        "rk2", Math.max(1, n / 5), seed + 2, false);
                shots += record(w, name, world, SimulationSettings.DEFAULT.withIntegrator(Integrator.EULER),
                        "euler", Math.max(1, n / 5), seed + 3, false);
            }
        }
        System.out.println(shots + " shots on " + courses + " courses -> " + out);
    }

    private static int record(PrintWriter w, String name, World world, SimulationSettings settings, String kind,
                              int n, long seed, boolean chip) {
        Simulator simulator = new Simulator(world, settings);
        SplittableRandom random = new SplittableRandom(seed);
        double max = world.physics().maxSpeed();
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        for (int i = 0; i < n; i++) {
            double x0 = world.course().start().x(), y0 = world.course().start().y();
            if (kind.equals("near")) {
                // From 0.2 to 2 m off the hole: the capture and drop rules decide many of these.
                double a = random.nextDouble() * 2 * Math.PI, r = 0.2 + 1.8 * random.nextDouble();
                x0 = hx + r * Math.cos(a);
                y0 = hy + r * Math.sin(a);
            }
            double angle = random.nextDouble() * 2 * Math.PI;
            double speed = max * (0.1 + 0.9 * random.nextDouble());
            if (kind.equals("aim") || kind.equals("near")) {
                // Towards the hole, a little off line, not too fast: the hole rules get their turn.
                angle = Math.atan2(hy - y0, hx - x0) + 0.1 * (random.nextDouble() - 0.5);
                speed = kind.equals("aim") ? max * (0.05 + 0.55 * random.nextDouble())
                        : Math.min(max, 0.3 + 2.7 * random.nextDouble());
            }
            double elevation = chip ? Math.toRadians(5 + 55 * random.nextDouble()) : 0;
            double horizontal = speed * Math.cos(elevation);
            double vx = horizontal * Math.cos(angle), vy = horizontal * Math.sin(angle);
            double vz = speed * Math.sin(elevation);
            Hash hash = new Hash();
            String line;
            try {
                ShotResult r = simulator.simulate(x0, y0, vx, vy, vz, hash);
                // The bots' path, without listener or events, must end the same.
                ShotResult bare = simulator.simulate(x0, y0, vx, vy, vz);
                boolean same = bare.outcome() == r.outcome() && bits(bare.endX()) == bits(r.endX())
                        && bits(bare.endY()) == bits(r.endY()) && bits(bare.time()) == bits(r.time())
                        && bare.steps() == r.steps();
                line = String.format("%s %s %d %s %d %d %x %x %x %x %016x%s", name, kind, i, r.outcome(), r.steps(),
                        r.events().size(), bits(r.endX()), bits(r.endY()), bits(r.endZ()), bits(r.time()), hash.h,
                        same ? "" : " BARE-DIFFERS");
            } catch (RuntimeException e) {
                line = String.format("%s %s %d THROWS %s %016x", name, kind, i, e.getClass().getSimpleName(), hash.h);
            }
            w.println(line);
        }
        return n;
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    /** A running hash of every state and event the stroke reports. */
    private static final class Hash implements TrajectoryListener {
        long h = 0x9E3779B97F4A7C15L;

        private void mix(double d) {
            h = (h ^ bits(d)) * 0xBF58476D1CE4E5B9L;
            h ^= h >>> 31;
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
        }

        @Override
        public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
            mix(t); mix(x); mix(y); mix(z); mix(vx); mix(vy); mix(vz);
        }

        @Override
        public void onEvent(StrokeEvent e) {
            mix(e.type().ordinal());
            mix(e.t()); mix(e.x()); mix(e.y()); mix(e.z()); mix(e.speedBefore()); mix(e.speedAfter());
        }
    }
}
