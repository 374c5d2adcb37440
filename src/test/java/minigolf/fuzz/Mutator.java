package minigolf.fuzz;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ContainerNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * Seeded mutations of a JSON file: deleted fields, swapped types, extreme and non-finite numbers,
 * deep nesting, huge arrays, truncation, binary garbage and bombs. The same seed gives the same bytes.
 */
final class Mutator {
    static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonNodeFactory F = JsonNodeFactory.instance;
    private static final List<String> FILE_FIELDS = List.of("file", "course", "source");
    static final String[] KINDS = {"delete", "swap-type", "extreme-number", "non-finite", "deep-nesting", "huge-array",
            "truncate", "garbage", "bomb", "duplicate-key", "hostile-path", "utf16"};

    private Mutator() {
    }

    /** One mutated file: its bytes and what was done (for the failure message and the regression file). */
    record Case(String kind, String detail, byte[] bytes) {
    }

    static Case mutate(String json, long seed) {
        Random r = new Random(seed);
        String kind = KINDS[r.nextInt(KINDS.length)];
        try {
            JsonNode root = MAPPER.readTree(json);
            switch (kind) {
                case "truncate" -> {
                    int cut = r.nextInt(Math.max(1, json.length()));
                    return new Case(kind, "cut at " + cut, json.substring(0, cut).getBytes(StandardCharsets.UTF_8));
                }
                case "garbage" -> {
                    byte[] b = json.getBytes(StandardCharsets.UTF_8);
                    int n = 1 + r.nextInt(16);
                    for (int i = 0; i < n; i++) b[r.nextInt(b.length)] = (byte) r.nextInt(256);
                    return new Case(kind, n + " random bytes", b);
                }
                case "utf16" -> {
                    return new Case(kind, "UTF-16", json.getBytes(r.nextBoolean() ? StandardCharsets.UTF_16
                            : StandardCharsets.UTF_16LE));
                }
                case "non-finite" -> {
                    // Text substitution: JSON has no NaN, so only a raw replacement can put one there.
                    String[] words = {"NaN", "Infinity", "-Infinity", "1e999", "-1e999", "1e-999"};
                    String w = words[r.nextInt(words.length)];
                    String out = json.replaceFirst("(?<=[:\\[,] ?)-?[0-9][0-9.eE+-]*", w);
                    return new Case(kind, w, out.getBytes(StandardCharsets.UTF_8));
                }
                case "duplicate-key" -> {
                    int brace = json.indexOf('{', 1);
                    if (brace < 0) brace = json.indexOf('{');
                    String out = brace >= 0 ? json.substring(0, brace + 1) + "\"x\": 1, \"x\": 2, " + json.substring(brace + 1) : json;
                    return new Case(kind, "duplicate x", out.getBytes(StandardCharsets.UTF_8));
                }
                default -> {
                    List<Slot> slots = new ArrayList<>();
                    collect(root, slots);
                    if (slots.isEmpty()) return new Case(kind, "nothing to mutate", json.getBytes(StandardCharsets.UTF_8));
                    // The fields that name a file: a model's, a round's hole course, a saved round's source.
                    List<Slot> files = slots.stream().filter(x -> x.field != null && FILE_FIELDS.contains(x.field)).toList();
                    Slot s = kind.equals("hostile-path") && !files.isEmpty() ? files.get(r.nextInt(files.size()))
                            : slots.get(r.nextInt(slots.size()));
                    String detail = s.path + ": " + apply(kind, s, r);
                    return new Case(kind, detail, MAPPER.writeValueAsBytes(root));
                }
            }
        } catch (Exception e) {
            throw new IllegalStateException("the mutator failed on seed " + seed, e);
        }
    }

    /** A place in the tree: a field of an object or an element of an array. */
    private record Slot(ContainerNode<?> parent, String field, int index, String path) {
        JsonNode get() {
            return field != null ? parent.get(field) : parent.get(index);
        }

        void set(JsonNode v) {
            if (field != null) ((ObjectNode) parent).set(field, v);
            else ((ArrayNode) parent).set(index, v);
        }

        void remove() {
            if (field != null) ((ObjectNode) parent).remove(field);
            else ((ArrayNode) parent).remove(index);
        }
    }

    private static void collect(JsonNode node, List<Slot> slots) {
        collect(node, "", slots, 0);
    }

    private static void collect(JsonNode node, String path, List<Slot> slots, int depth) {
        if (node.isObject()) {
            for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                String p = path.isEmpty() ? e.getKey() : path + "." + e.getKey();
                slots.add(new Slot((ObjectNode) node, e.getKey(), -1, p));
                collect(e.getValue(), p, slots, depth + 1);
            }
        } else if (node.isArray()) {
            // Big arrays (grid rows) are sampled so that every part of a file gets picked now and then.
            int n = node.size(), step = Math.max(1, n / 8);
            for (int i = 0; i < n; i += step) {
                slots.add(new Slot((ArrayNode) node, null, i, path + "[" + i + "]"));
                collect(node.get(i), path + "[" + i + "]", slots, depth + 1);
            }
        }
    }

    private static String apply(String kind, Slot s, Random r) {
        JsonNode v = s.get();
        switch (kind) {
            case "delete" -> {
                s.remove();
                return "deleted";
            }
            case "swap-type" -> {
                JsonNode[] others = {F.textNode("7"), F.numberNode(7), F.booleanNode(true), F.nullNode(), F.objectNode(),
                        F.arrayNode(), F.arrayNode().add(1).add(2), F.textNode("")};
                JsonNode w = others[r.nextInt(others.length)];
                s.set(w);
                return "now " + w;
            }
            case "extreme-number" -> {
                double[] xs = {0, -0.0, 1e308, -1e308, Double.MIN_VALUE, -Double.MIN_VALUE, 1e-9, 1e9, 1e20, -1,
                        2147483648.0, 4.9e-324};
                long[] ls = {Long.MAX_VALUE, Long.MIN_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, -1, 0};
                if (r.nextBoolean()) {
                    double x = xs[r.nextInt(xs.length)];
                    s.set(F.numberNode(x));
                    return "now " + x;
                }
                long l = ls[r.nextInt(ls.length)];
                s.set(F.numberNode(l));
                return "now " + l;
            }
            case "deep-nesting" -> {
                int depth = 20 + r.nextInt(900);
                JsonNode w = v;
                for (int i = 0; i < depth; i++) w = r.nextBoolean() ? F.arrayNode().add(w) : F.objectNode().set("a", w);
                s.set(w);
                return "wrapped " + depth + " deep";
            }
            case "huge-array" -> {
                int n = 1000 + r.nextInt(300_000);
                JsonNode element = v.isArray() && v.size() > 0 ? v.get(0) : v;
                // At most about 12 MB written: past every file limit, but within the test's heap (a grid's row
                // copied 300,000 times would be gigabytes).
                n = (int) Math.min(n, 12_000_000L / Math.max(1, element.toString().length() + 1));
                ArrayNode a = F.arrayNode(n);
                for (int i = 0; i < n; i++) a.add(element);
                s.set(a);
                return n + " copies";
            }
            case "bomb" -> {
                int which = r.nextInt(3);
                if (which == 0) {
                    s.set(F.textNode("x".repeat(1 + r.nextInt(9_000_000))));
                    return "a long string";
                }
                if (which == 1) {
                    String e = "x" + "*x".repeat(r.nextInt(60_000));
                    s.set(F.textNode(e));
                    return "a long product";
                }
                s.set(F.textNode("exp(exp(exp(exp(x))))"));
                return "exp(exp(exp(exp(x))))";
            }
            case "hostile-path" -> {
                String[] paths = {"/etc/passwd", "../../../../etc/passwd", "/dev/zero", "/proc/self/environ",
                        "models/../../../etc/hostname", "C:\\\\Windows\\\\win.ini", "models/", "", "\u0000"};
                String p = paths[r.nextInt(paths.length)];
                s.set(F.textNode(p));
                return "now " + p;
            }
            default -> throw new IllegalArgumentException(kind);
        }
    }
}
