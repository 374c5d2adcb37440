package minigolf.cli;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

@Command(name = "bench-limits",
        description = {"Writes a course at each documented limit (the worst cases an accepted file can ask for) and",
                "times loading it as the game does (read, validate, compile the terrain, build the collision scene).",
                "After loading the bundled courses once (as the game's menu does), prints each case's first load",
                "time, its best of three, the CPU time of that load (all the process's threads: GC and compiler",
                "included), the heap's peak during the first load and the file size; exits 1 if a first load takes",
                "2 s or more of CPU time (on a free core, 2 s or more). Run it with -Xmx1g to check the memory bound too."})
final class BenchLimitsCommand implements Callable<Integer> {
    static final double MAX_SECONDS = 2.0;

    @Spec
    CommandSpec spec;

    @Option(names = "--dir", paramLabel = "DIR", description = "Where the cases are written (default: a temporary folder, removed after).")
    Path dir;

    @Override
    public Integer call() throws IOException {
        boolean temporary = dir == null;
        if (!temporary && Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new UserError("--dir: " + dir + " is a file, not a folder");
        }
        Path folder = temporary ? Files.createTempDirectory("minigolf-limits") : dir;
        try {
            Map<String, Path> cases;
            try {
                cases = LimitCases.write(folder);
            } catch (IOException e) {
                throw new UserError("--dir: cannot write the cases in " + folder + ": " + e.getMessage());
            }
            warmUp();
            ArrayNode rows = Json.MAPPER.createArrayNode();
            boolean ok = true;
            for (Map.Entry<String, Path> c : cases.entrySet()) {
                System.gc();
                long before = heapUsed();
                ManagementFactory.getMemoryPoolMXBeans().forEach(MemoryPoolMXBean::resetPeakUsage);
                long start = System.nanoTime(), cpuStart = cpuNanos();
                try {
                    World.load(c.getValue());
                } catch (CourseException e) {
                    throw new UserError("bench-limits: a case at the limits was refused: " + e.getMessage());
                }
                double seconds = (System.nanoTime() - start) / 1e9, cpu = (cpuNanos() - cpuStart) / 1e9;
                long peak = heapPeak();
                double best = seconds;
                for (int k = 0; k < 2; k++) {
                    long again = System.nanoTime();
                    loadQuietly(c.getValue());
                    best = Math.min(best, (System.nanoTime() - again) / 1e9);
                }
                ObjectNode row = rows.addObject();
                row.put("case", c.getKey());
                row.put("fileBytes", size(c.getValue()));
                row.put("loadSeconds", Math.round(seconds * 1000) / 1000.0);
                row.put("bestOf3Seconds", Math.round(best * 1000) / 1000.0);
                // The verdict is on CPU time: a shared machine stretches the wall time (load 15 on 2 cores: 2.3 s for 0.3 s of CPU).
                row.put("loadCpuSeconds", Math.round(cpu * 1000) / 1000.0);
                row.put("heapPeakMB", Math.round((peak) / 1e5) / 10.0);
                row.put("heapBeforeMB", Math.round(before / 1e5) / 10.0);
                ok &= cpu < MAX_SECONDS;
            }
            ObjectNode out = Json.object();
            out.put("maxHeapMB", Math.round(Runtime.getRuntime().maxMemory() / 1e5) / 10.0);
            out.put("processors", Runtime.getRuntime().availableProcessors());
            out.set("cases", rows);
            out.put("allUnderSeconds", ok);
            spec.commandLine().getOut().println(Json.write(out));
            return ok ? 0 : 1;
        } finally {
            if (temporary) deleteTree(folder);
        }
    }

    /**
     * The game has loaded its menu's courses before a player opens one: the same with the bundled
     * courses (grid, obstacles, the windmill model, zones) brings the loader's classes in, so each
     * case's first load measures its own data, not the JVM's start.
     */
    private static void warmUp() {
        for (String name : new String[]{"grid-256.json", "lake-obstacles.json", "windmill.json", "sand.json", "lake.json"}) {
            try (java.io.InputStream in = BenchLimitsCommand.class.getResourceAsStream("/courses/" + name)) {
                if (in != null) World.parse(new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8), "courses/" + name);
            } catch (IOException | CourseException e) {
                throw new UserError("bench-limits: the bundled course " + name + " does not load: " + e.getMessage());
            }
        }
    }

    private static void loadQuietly(Path file) {
        try {
            World.load(file);
        } catch (CourseException e) {
            throw new UserError("bench-limits: " + e.getMessage());
        }
    }

    private static long heapUsed() {
        Runtime r = Runtime.getRuntime();
        return r.totalMemory() - r.freeMemory();
    }

    /** The sum of the heap pools' peaks since the reset: at least the heap's true peak. */
    /** The process's CPU time, every thread's (the loader's, the garbage collector's, the compiler's). */
    private static long cpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
    }

    private static long heapPeak() {
        long sum = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP && pool.getPeakUsage() != null) sum += pool.getPeakUsage().getUsed();
        }
        return sum;
    }

    private static long size(Path file) throws IOException {
        long total = Files.size(file);
        try (Stream<Path> siblings = Files.list(file.getParent())) {
            for (Path p : (Iterable<Path>) siblings::iterator) {
                if (p.toString().endsWith(".obj") && Files.readString(file).contains(p.getFileName().toString())) {
                    total += Files.size(p);
                }
            }
        }
        return total;
    }

    private static void deleteTree(Path folder) {
        try (Stream<Path> walk = Files.walk(folder)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException ignored) {
            // a temporary folder left behind
        }
    }
}
