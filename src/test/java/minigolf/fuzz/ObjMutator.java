package minigolf.fuzz;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

/**
 * Seeded mutations of a Wavefront .obj model, as text: lines deleted or repeated, numbers made
 * extreme or not numbers, face indices out of range, zero or negative, faces of one vertex or
 * thousands, a hostile material library, long lines, truncation, random bytes and UTF-16. The same
 * seed gives the same bytes.
 */
final class ObjMutator {
    static final String[] KINDS = {"delete-lines", "repeat-lines", "bad-number", "bad-index", "odd-face", "hostile-mtllib",
            "long-line", "truncate", "garbage", "utf16", "many-faces"};

    private ObjMutator() {
    }

    record Case(String kind, String detail, byte[] bytes) {
    }

    static Case mutate(String obj, long seed) {
        Random r = new Random(seed);
        String kind = KINDS[r.nextInt(KINDS.length)];
        List<String> lines = new ArrayList<>(Arrays.asList(obj.split("\n", -1)));
        int at = r.nextInt(lines.size());
        String detail;
        switch (kind) {
            case "delete-lines" -> {
                int n = 1 + r.nextInt(Math.max(1, lines.size() / 4));
                for (int i = 0; i < n && !lines.isEmpty(); i++) lines.remove(r.nextInt(lines.size()));
                detail = n + " lines deleted";
            }
            case "repeat-lines" -> {
                int n = 1 + r.nextInt(20_000);
                String line = lines.get(at);
                for (int i = 0; i < n; i++) lines.add(at, line);
                detail = "line " + at + " x" + n;
            }
            case "bad-number" -> {
                String[] words = {"NaN", "Infinity", "-Infinity", "1e999", "1e308", "-1e308", "4.9e-324", "x", "", "1.2.3", "0x10"};
                String w = words[r.nextInt(words.length)];
                int v = vertexLine(lines, r);
                String[] t = lines.get(v).split(" ");
                if (t.length > 1) t[1 + r.nextInt(t.length - 1)] = w;
                lines.set(v, String.join(" ", t));
                detail = "line " + v + ": " + w;
            }
            case "bad-index" -> {
                String[] indices = {"0", "-1", "-100000", "2147483648", "99999999999", "1/2/3/4", "//", "1//x", "-0"};
                String w = indices[r.nextInt(indices.length)];
                int f = faceLine(lines, r);
                String[] t = lines.get(f).split(" ");
                if (t.length > 1) t[1 + r.nextInt(t.length - 1)] = w;
                lines.set(f, String.join(" ", t));
                detail = "face line " + f + ": " + w;
            }
            case "odd-face" -> {
                int n = r.nextBoolean() ? r.nextInt(3) : 3 + r.nextInt(5_000);
                StringBuilder f = new StringBuilder("f");
                for (int i = 0; i < n; i++) f.append(' ').append(1 + r.nextInt(3));
                lines.add(at, f.toString());
                detail = "a face of " + n + " vertices";
            }
            case "hostile-mtllib" -> {
                String[] paths = {"/etc/passwd", "../../../../etc/passwd", "/dev/zero", "/proc/self/environ", "..", "", "C:\\Windows\\win.ini"};
                String p = paths[r.nextInt(paths.length)];
                lines.add(0, "mtllib " + p);
                detail = "mtllib " + p;
            }
            case "long-line" -> {
                int n = 1 + r.nextInt(2_000_000);
                lines.add(at, (r.nextBoolean() ? "# " : "v 1 2 ") + "9".repeat(n));
                detail = "a line of " + n + " characters";
            }
            case "many-faces" -> {
                int n = 10_000 + r.nextInt(60_000);
                for (int i = 0; i < n; i++) lines.add("f 1 2 3");
                detail = n + " more faces";
            }
            case "truncate" -> {
                int cut = r.nextInt(Math.max(1, obj.length()));
                return new Case(kind, "cut at " + cut, obj.substring(0, cut).getBytes(StandardCharsets.UTF_8));
            }
            case "garbage" -> {
                byte[] b = obj.getBytes(StandardCharsets.UTF_8);
                int n = 1 + r.nextInt(16);
                for (int i = 0; i < n; i++) b[r.nextInt(b.length)] = (byte) r.nextInt(256);
                return new Case(kind, n + " random bytes", b);
            }
            case "utf16" -> {
                return new Case(kind, "UTF-16", obj.getBytes(StandardCharsets.UTF_16LE));
            }
            default -> throw new IllegalArgumentException(kind);
        }
        return new Case(kind, detail, String.join("\n", lines).getBytes(StandardCharsets.UTF_8));
    }

    private static int vertexLine(List<String> lines, Random r) {
        return someLine(lines, r, "v ");
    }

    private static int faceLine(List<String> lines, Random r) {
        return someLine(lines, r, "f ");
    }

    /** A random line starting with {@code prefix}, or any line when there is none. */
    private static int someLine(List<String> lines, Random r, String prefix) {
        List<Integer> matching = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) if (lines.get(i).startsWith(prefix)) matching.add(i);
        return matching.isEmpty() ? r.nextInt(lines.size()) : matching.get(r.nextInt(matching.size()));
    }
}
