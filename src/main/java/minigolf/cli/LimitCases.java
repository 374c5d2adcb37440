package minigolf.cli;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.function.IntFunction;
import minigolf.course.Limits;
import minigolf.expr.Expression;
import minigolf.expr.ExpressionException;

/**
 * Course files that ask for as much as the limits allow ({@link Limits}), one per limit: the worst
 * cases that every accepted file must still load quickly. Deterministic.
 */
final class LimitCases {
    private LimitCases() {
    }

    /** Writes the cases into {@code dir}; returns name -> course file. */
    static Map<String, Path> write(Path dir) throws IOException {
        Files.createDirectories(dir);
        Map<String, Path> cases = new LinkedHashMap<>();
        cases.put("grid 512x512 with both friction grids", grid(dir));
        cases.put(Limits.OBSTACLES + " walls across the course", walls(dir));
        cases.put(Limits.OBSTACLES + " boxes, one per wall tile (a classic track's walls drawn tile by tile)", tiles(dir));
        cases.put("one model of " + Limits.MODEL_TRIANGLES + " triangles and " + Limits.MODEL_VERTICES + " vertices",
                bigModel(dir));
        cases.put(Limits.OBSTACLES + " models, " + Limits.TRIANGLES + " triangles in all, 100 m wide", manyModels(dir));
        cases.put(Limits.ZONES + " zones, " + Limits.ALL_POLYGON_POINTS + " polygon points", zones(dir));
        cases.put("the longest expression that compiles", expression(dir));
        cases.put("a model file of " + (Limits.MODEL_FILE_BYTES >> 20) + " MiB, mostly comments", commentModel(dir));
        cases.put("a course file of " + (Limits.COURSE_FILE_BYTES >> 20) + " MiB, mostly whitespace", padded(dir));
        return cases;
    }

    private static String course(String terrain, String bounds, String zones, String obstacles) {
        return "{\"format\": 1, \"name\": \"limits\", \"terrain\": " + terrain + ", \"bounds\": " + bounds
                + ", \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2, \"maxSpeed\": 5},"
                + " \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1},"
                + " \"zones\": " + zones + ", \"obstacles\": " + obstacles + "}\n";
    }

    private static final String BOUNDS = "{\"min\": [-5, -5], \"max\": [5, 5]}";

    static Path grid(Path dir) throws IOException {
        int n = (int) Math.sqrt(Limits.GRID_NODES);
        Path f = dir.resolve("grid.json");
        try (Writer w = Files.newBufferedWriter(f, StandardCharsets.UTF_8)) {
            w.write("{\"format\": 1, \"name\": \"limits\", \"terrain\": {\"grid\": {\"origin\": [-5, -5], \"spacing\": "
                    + (10.0 / (n - 1)) + ", \"heights\": ");
            matrix(w, n, (i) -> String.format(Locale.ROOT, "%.3f", 0.1 + 0.05 * Math.sin(i * 0.01)));
            w.write(", \"kineticFriction\": ");
            matrix(w, n, (i) -> i % 7 == 0 ? "0.3" : "0.1");
            w.write(", \"staticFriction\": ");
            matrix(w, n, (i) -> i % 7 == 0 ? "0.4" : "0.2");
            w.write("}}, \"bounds\": " + BOUNDS + ", \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2,"
                    + " \"maxSpeed\": 5}, \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1}}\n");
        }
        return f;
    }

    private static void matrix(Writer w, int n, IntFunction<String> value) throws IOException {
        w.write('[');
        for (int j = 0; j < n; j++) {
            w.write(j == 0 ? "[" : ",[");
            for (int i = 0; i < n; i++) {
                if (i > 0) w.write(',');
                w.write(value.apply(j * n + i));
            }
            w.write(']');
        }
        w.write(']');
    }

    private static Path walls(Path dir) throws IOException {
        StringBuilder sb = new StringBuilder("[");
        for (int k = 0; k < Limits.OBSTACLES; k++) {
            double t = (double) k / Limits.OBSTACLES;
            if (k > 0) sb.append(',');
            sb.append(String.format(Locale.ROOT, "{\"type\": \"wall\", \"from\": [-500, %.4f], \"to\": [500, %.4f],"
                    + " \"thickness\": 0.05, \"height\": 0.1}", -500 + 1000 * t, 500 - 1000 * t));
        }
        Path f = dir.resolve("walls.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", "{\"min\": [-500, -500], \"max\": [500, 500]}", "[]",
                sb.append(']').toString()));
        return f;
    }

    /** Boxes of 0.25 m side by side on a 50-wide grid of tiles, as a classic track converted one box per wall tile. */
    private static Path tiles(Path dir) throws IOException {
        StringBuilder sb = new StringBuilder("[");
        double tile = 0.25;
        for (int k = 0; k < Limits.OBSTACLES; k++) {
            double x = -6.25 + tile * (k % 50), y = -6.25 + tile * (k / 50);
            if (k > 0) sb.append(',');
            sb.append(String.format(Locale.ROOT, "{\"type\": \"box\", \"min\": [%.2f, %.2f, 0.1], \"max\": [%.2f, %.2f, 0.2]}",
                    x, y, x + tile, y + tile));
        }
        Path f = dir.resolve("tiles.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", "{\"min\": [-8, -8], \"max\": [8, 8]}", "[]",
                sb.append(']').toString()).replace("[-4, 0]", "[-7, 0]").replace("[4, 0]", "[7, 0]"));
        return f;
    }

    /** A grid of quads: (side+1)^2 vertices, 2 side^2 triangles. */
    private static void gridModel(Path file, int side, int vertices, String comment) throws IOException {
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            int written = 0;
            for (int j = 0; j <= side; j++) {
                for (int i = 0; i <= side; i++, written++) {
                    w.write(String.format(Locale.ROOT, "v %.4f %.4f %.4f\n", (double) i / side - 0.5, (double) j / side - 0.5,
                            0.05 * Math.sin(i + j)));
                }
            }
            for (; written < vertices; written++) w.write("v 0 0 0\n");
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    int a = j * (side + 1) + i + 1, b = a + 1, c = a + side + 1, d = c + 1;
                    w.write("f " + a + " " + b + " " + d + "\nf " + a + " " + d + " " + c + "\n");
                }
            }
            if (comment != null) w.write(comment);
        }
    }

    private static Path bigModel(Path dir) throws IOException {
        int side = (int) Math.floor(Math.sqrt(Limits.MODEL_TRIANGLES / 2.0));
        gridModel(dir.resolve("big.obj"), side, Limits.MODEL_VERTICES, null);
        Path f = dir.resolve("big-model.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", BOUNDS, "[]",
                "[{\"type\": \"model\", \"file\": \"big.obj\", \"position\": [0, 0, 0.1], \"scale\": 8}]"));
        return f;
    }

    private static Path manyModels(Path dir) throws IOException {
        int perModel = Limits.TRIANGLES / Limits.OBSTACLES;
        int side = (int) Math.floor(Math.sqrt(perModel / 2.0));
        gridModel(dir.resolve("small.obj"), side, 0, null);
        StringBuilder sb = new StringBuilder("[");
        for (int k = 0; k < Limits.OBSTACLES; k++) {
            if (k > 0) sb.append(',');
            sb.append(String.format(Locale.ROOT, "{\"type\": \"model\", \"file\": \"small.obj\", \"position\": [%.3f, %.3f, 0.1],"
                    + " \"rotationDeg\": %d, \"scale\": 100}", -40 + 80.0 * (k % 32) / 31, -40 + 80.0 * (k / 32) / 31, k));
        }
        Path f = dir.resolve("many-models.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", "{\"min\": [-50, -50], \"max\": [50, 50]}", "[]",
                sb.append(']').toString()));
        return f;
    }

    private static Path zones(Path dir) throws IOException {
        StringBuilder sb = new StringBuilder("[");
        int polygons = Limits.ALL_POLYGON_POINTS / Limits.POLYGON_POINTS;
        for (int z = 0; z < Limits.ZONES; z++) {
            if (z > 0) sb.append(',');
            double cx = -4 + 8.0 * (z % 25) / 24, cy = -4 + 8.0 * (z / 25) / 19;
            String shape;
            if (z < polygons) {
                StringBuilder pts = new StringBuilder("[");
                for (int k = 0; k < Limits.POLYGON_POINTS; k++) {
                    double a = 2 * Math.PI * k / Limits.POLYGON_POINTS, r = 0.3 + 0.1 * Math.sin(7 * a);
                    if (k > 0) pts.append(',');
                    pts.append(String.format(Locale.ROOT, "[%.5f, %.5f]", cx + r * Math.cos(a), cy + r * Math.sin(a)));
                }
                shape = "{\"type\": \"polygon\", \"points\": " + pts.append(']') + "}";
            } else {
                shape = String.format(Locale.ROOT, "{\"type\": \"circle\", \"center\": [%.3f, %.3f], \"radius\": 0.15}", cx, cy);
            }
            sb.append("{\"shape\": ").append(shape).append(", \"kineticFriction\": 0.3, \"staticFriction\": 0.4}");
        }
        Path f = dir.resolve("zones.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", BOUNDS, sb.append(']').toString(), "[]"));
        return f;
    }

    /**
     * Terms 0.001*sin(k.1*x + y), in parenthesised groups of {@link #GROUP}, added until the
     * expression no longer compiles: the JVM's 64 KiB method limit is what ends it (516 terms fit,
     * 517 do not). Written as one chain, 0.1 + t0 + t1 + ..., the tree's height limit of 300 comes
     * first (295 terms fit, 296 do not); the groups keep the tree low, so this is the costlier case.
     */
    static String longestCompilingExpression() {
        return terms(largestCompiling(GROUP), GROUP);
    }

    /** Terms per parenthesised group in {@link #longestCompilingExpression()}. */
    static final int GROUP = 50;

    /** The most terms, in groups of {@code group} (one chain when as large as the count), that still compile. */
    static int largestCompiling(int group) {
        int low = 1, high = 20_000, best = 0;
        while (low <= high) {
            int mid = (low + high) >>> 1;
            if (compileProblem(terms(mid, group)) == null) {
                best = mid;
                low = mid + 1;
            } else {
                high = mid - 1;
            }
        }
        return best;
    }

    /** Why the expression does not compile, or null when it does. */
    static String compileProblem(String expression) {
        try {
            Expression.parse(expression).compile();
            return null;
        } catch (ExpressionException e) {
            return e.getMessage();
        }
    }

    /** 0.1 + (t0 + ... + t[group-1]) + (...) ..., n terms in all. */
    static String terms(int n, int group) {
        StringBuilder sb = new StringBuilder("0.1");
        for (int k = 0; k < n; k++) {
            sb.append(k % group == 0 ? "+(" : "+").append("0.001*sin(").append(k).append(".1*x+y)");
            if (k % group == group - 1 || k == n - 1) sb.append(')');
        }
        return sb.toString();
    }

    private static Path expression(Path dir) throws IOException {
        Path f = dir.resolve("expression.json");
        Files.writeString(f, course("{\"height\": \"" + longestCompilingExpression() + "\"}", BOUNDS, "[]", "[]"));
        return f;
    }

    /** A name may have only {@link Limits#NAME_CHARS} characters: the file is filled up with whitespace between its fields. */
    private static Path padded(Path dir) throws IOException {
        String c = course("{\"height\": \"0.1\"}", BOUNDS, "[]", "[]");
        String name = "n".repeat(Limits.NAME_CHARS);
        String pad = " \n".repeat(((int) Limits.COURSE_FILE_BYTES - c.length() - name.length() - 16) / 2);
        Path f = dir.resolve("padded.json");
        Files.writeString(f, c.replace("\"name\": \"limits\"", "\"name\": \"" + name + "\"" + pad));
        return f;
    }

    private static Path commentModel(Path dir) throws IOException {
        StringBuilder comment = new StringBuilder();
        String line = "# " + "x".repeat(77) + "\n";
        long room = Limits.MODEL_FILE_BYTES - 200;
        while (comment.length() + line.length() < room) comment.append(line);
        Path obj = dir.resolve("comments.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + comment);
        Path f = dir.resolve("comment-model.json");
        Files.writeString(f, course("{\"height\": \"0.1\"}", BOUNDS, "[]",
                "[{\"type\": \"model\", \"file\": \"comments.obj\", \"position\": [0, 0, 0.1]}]"));
        return f;
    }
}
