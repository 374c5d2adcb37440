package minigolf.game;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;
import minigolf.course.Limits;
import minigolf.io.TextFiles;

/** Strict reading of the game's own JSON files, field by field, with one-line errors naming the field. */
final class JsonFields {
    static final ObjectMapper MAPPER = JsonMapper.builder(JsonFactory.builder()
                    .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(Limits.JSON_DEPTH).build())
                    .build())
            .enable(DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .disable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
            .build();

    private final String source;

    JsonFields(String source) {
        this.source = source;
    }

    /** The file's text: a regular UTF-8 file of at most {@code maxBytes} (see {@link TextFiles}). */
    static String readText(Path file, long maxBytes) throws SaveGameException {
        try {
            return TextFiles.read(file, maxBytes);
        } catch (TextFiles.TextFileException e) {
            throw new SaveGameException(String.valueOf(file), null, "cannot read: " + e.getMessage());
        }
    }

    JsonNode parse(String json) throws SaveGameException {
        String blank = TextFiles.blankProblem(json);
        if (blank != null) throw new SaveGameException(source, null, "not valid JSON: " + blank);
        try {
            JsonNode root = MAPPER.readTree(json.startsWith("\uFEFF") ? json.substring(1) : json);
            if (root == null || root.isMissingNode()) throw new SaveGameException(source, null, "not valid JSON: the file is empty");
            return object(root, null);
        } catch (com.fasterxml.jackson.core.exc.StreamConstraintsException e) {
            String m = String.valueOf(e.getOriginalMessage());
            throw new SaveGameException(source, null, "not valid JSON: " + (m.contains("nesting depth")
                    ? "nested more than " + Limits.JSON_DEPTH + " levels deep (the limit)" : m.lines().findFirst().orElse("")));
        } catch (JsonProcessingException e) {
            throw new SaveGameException(source, null, minigolf.io.JsonSyntax.problem(e), e);
        }
    }

    SaveGameException error(String path, String problem) {
        return new SaveGameException(source, path, problem);
    }

    JsonNode object(JsonNode node, String path) throws SaveGameException {
        if (node == null || !node.isObject()) throw error(path, "must be an object" + (node == null ? "" : ", got " + got(node)));
        return node;
    }

    void onlyFields(JsonNode node, String path, List<String> allowed) throws SaveGameException {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!allowed.contains(f)) throw error(join(path, f), "unknown field (expected one of " + String.join(", ", allowed) + ")");
        }
    }

    /** The field's value, null included (each caller's type check says "..., got null"); an absent field "is missing". */
    JsonNode field(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = node.get(name);
        if (v == null || v.isMissingNode()) throw error(join(path, name), "is missing");
        return v;
    }

    /** What a value is, for "must be ..., got X": a number as written, null, true, false, a string, an array, an object. */
    static String got(JsonNode v) {
        if (v.isNumber() || v.isNull() || v.isBoolean()) return v.asText();
        if (v.isTextual()) return "a string";
        return v.isArray() ? "an array" : "an object";
    }

    double number(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        if (!v.isNumber()) throw error(join(path, name), "must be a number, got " + got(v));
        double d = v.doubleValue();
        if (!Double.isFinite(d)) throw error(join(path, name), "must be a finite number");
        return d;
    }

    int integer(JsonNode node, String path, String name, int min, int max) throws SaveGameException {
        JsonNode v = field(node, path, name);
        if (!v.isIntegralNumber()) throw error(join(path, name), "must be a whole number, got " + got(v));
        if (!v.canConvertToInt() || v.intValue() < min || v.intValue() > max) {
            throw error(join(path, name), "must be " + min + " to " + max + ", got " + v.asText());
        }
        int i = v.intValue();
        if (i < min || i > max) throw error(join(path, name), "must be " + min + " to " + max + ", got " + i);
        return i;
    }

    boolean bool(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        if (!v.isBoolean()) throw error(join(path, name), "must be true or false, got " + got(v));
        return v.booleanValue();
    }

    String text(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        if (!v.isTextual()) throw error(join(path, name), "must be a string, got " + got(v));
        return v.textValue();
    }

    /** {@code text} itself, refused when it has more than {@code limit} characters (a name shown on screen). */
    String shortText(String text, String path, int limit) throws SaveGameException {
        String problem = Limits.tooLong(text, limit);
        if (problem != null) throw error(path, problem);
        return text;
    }

    double[] vec(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        String p = join(path, name);
        if (!v.isArray() || v.size() != 2) throw error(p, "must be [x, y]");
        double[] out = new double[2];
        for (int i = 0; i < 2; i++) {
            if (!v.get(i).isNumber() || !Double.isFinite(v.get(i).doubleValue())) throw error(p + "[" + i + "]", "must be a finite number");
            out[i] = v.get(i).doubleValue();
        }
        return out;
    }

    /**
     * A stroke's velocity: [vx, vy] (a putt, as in every file from before chips) or [vx, vy, vz]
     * with vz &gt;= 0 (a chip). Always returns three numbers.
     */
    double[] velocity(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        String p = join(path, name);
        if (!v.isArray() || v.size() < 2 || v.size() > 3) throw error(p, "must be [vx, vy] or [vx, vy, vz]");
        double[] out = new double[3];
        for (int i = 0; i < v.size(); i++) {
            if (!v.get(i).isNumber() || !Double.isFinite(v.get(i).doubleValue())) throw error(p + "[" + i + "]", "must be a finite number");
            out[i] = v.get(i).doubleValue();
        }
        if (out[2] < 0) throw error(p + "[2]", "must be 0 or more (the ball is hit upwards or along the ground)");
        return out;
    }

    JsonNode array(JsonNode node, String path, String name) throws SaveGameException {
        JsonNode v = field(node, path, name);
        if (!v.isArray()) throw error(join(path, name), "must be an array, got " + got(v));
        return v;
    }

    /** A value from the file for a message: quoted, one line, cut short. */
    static String shown(String value) {
        String v = value.length() > 40 ? value.substring(0, 37) + "..." : value;
        StringBuilder sb = new StringBuilder("\"");
        for (char c : v.toCharArray()) sb.append(Character.isISOControl(c) ? '?' : c);
        return sb.append('"').toString();
    }

    static String join(String path, String name) {
        return path == null || path.isEmpty() ? name : path + "." + name;
    }
}
