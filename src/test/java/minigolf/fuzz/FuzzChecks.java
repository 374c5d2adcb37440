package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import minigolf.course.CourseException;

/**
 * What every fuzzed case must satisfy, shared by the fuzz tests: loaded, it gives JSON of finite
 * numbers; refused, one line that starts with the file's name, says something, shows no internal
 * error or stack trace and no system file's content. Collects the failures and counts the outcomes.
 */
final class FuzzChecks {
    private final List<String> failures = new ArrayList<>();
    /** This thread's CPU time when the checks began (the report gives the cases' CPU time: comparable on a loaded machine). */
    private final long cpuStart = java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
    private final Map<String, int[]> outcomes = new TreeMap<>();
    private int cases;

    static Path projectDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."));
    }

    /** Every course file the game ships: courses/ and every folder below it but models/ and rounds/. */
    static List<Path> bundledCourses() throws IOException {
        Path courses = projectDir().resolve("courses");
        try (Stream<Path> s = Files.walk(courses)) {
            return s.filter(p -> p.toString().endsWith(".json"))
                    .filter(p -> !courses.relativize(p).startsWith("models") && !courses.relativize(p).startsWith("rounds"))
                    .sorted().toList();
        }
    }

    void started() {
        cases++;
    }

    int cases() {
        return cases;
    }

    void count(String kind, boolean accepted) {
        outcomes.computeIfAbsent(kind, k -> new int[2])[accepted ? 0 : 1]++;
    }

    void failure(String what) {
        failures.add(what);
    }

    static String describe(String name, long seed, Mutator.Case c) {
        return name + " seed " + seed + " (" + c.kind() + ": " + shorten(c.detail()) + ")";
    }

    static String shorten(String s) {
        return s.length() > 120 ? s.substring(0, 117) + "..." : s;
    }

    /** One case's load and what is done with what it loaded; a {@link CourseException} refuses the file. */
    interface Load {
        void run() throws CourseException, IOException;
    }

    /**
     * Runs one case: loaded, it counts as accepted under {@code kind}; refused by a
     * {@link CourseException}, as refused, and the message must pass {@link #oneLine} with
     * {@code prefix}; any other exception or error thrown is a failure (an I/O error of the test's
     * own files ends the test).
     */
    void loadOrRefuse(String kind, String what, String prefix, Load load) throws IOException {
        try {
            load.run();
            count(kind, true);
        } catch (CourseException e) {
            count(kind, false);
            oneLine(what, e.getMessage() + "\n", prefix);
        } catch (RuntimeException | Error e) {
            failure(what + ": threw " + e);
        }
    }

    /** A refusal: one line, starting with {@code prefix}, saying something, no internal error, no system file's content. */
    void oneLine(String what, String err, String prefix) {
        String e = err.endsWith("\n") ? err.substring(0, err.length() - 1) : err;
        if (e.isEmpty() || e.contains("\n")) {
            failures.add(what + ": not one line: " + shorten(err));
        } else if (!e.startsWith(prefix)) {
            failures.add(what + ": does not start with " + prefix + ": " + shorten(e));
        } else if (e.contains("internal error") || e.contains("Exception") || e.contains("\tat ")) {
            failures.add(what + ": an internal error: " + shorten(e));
        } else if (e.length() - prefix.length() < 8) {
            failures.add(what + ": says nothing: " + e);
        } else if (e.contains("root:") || e.contains("Unrecognized token 'root")) {
            failures.add(what + ": a system file's content was echoed: " + shorten(e));
        }
    }

    void finiteJson(String what, String json) {
        try {
            JsonNode root = Mutator.MAPPER.readTree(json);
            if (root == null || !root.isObject()) {
                failures.add(what + ": output is not a JSON object: " + shorten(json));
                return;
            }
            String bad = nonFinite(root, "");
            if (bad != null) failures.add(what + ": a non-finite number at " + bad);
        } catch (IOException e) {
            failures.add(what + ": output is not valid JSON: " + shorten(json));
        }
    }

    private static String nonFinite(JsonNode n, String path) {
        if (n.isNumber()) return Double.isFinite(n.doubleValue()) ? null : path;
        if (n.isTextual()) {
            String t = n.textValue();
            return t.equals("NaN") || t.endsWith("Infinity") ? path : null;
        }
        if (n.isObject()) {
            for (Iterator<String> it = n.fieldNames(); it.hasNext(); ) {
                String f = it.next();
                String bad = nonFinite(n.get(f), path + "." + f);
                if (bad != null) return bad;
            }
        }
        if (n.isArray()) {
            for (int i = 0; i < n.size(); i++) {
                String bad = nonFinite(n.get(i), path + "[" + i + "]");
                if (bad != null) return bad;
            }
        }
        return null;
    }

    /** Prints the outcomes and fails with the first failures, if any; {@code atLeast} cases must have run. */
    void report(String title, int atLeast) {
        double cpu = (java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime() - cpuStart) / 1e9;
        StringBuilder summary = new StringBuilder(String.format(java.util.Locale.ROOT, "%s: %d cases in %.1f s of CPU (accepted/refused):",
                title, cases, cpu));
        outcomes.forEach((k, v) -> summary.append(' ').append(k).append(' ').append(v[0]).append('/').append(v[1]));
        System.out.println(summary);
        if (cases < atLeast) fail("at least " + atLeast + " cases, ran " + cases);
        if (!failures.isEmpty()) {
            fail(failures.size() + " of " + cases + " cases failed; the first ones:\n"
                    + String.join("\n", failures.subList(0, Math.min(20, failures.size()))));
        }
    }
}
