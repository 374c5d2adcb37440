package minigolf.online;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Iterator;
import java.util.List;

/**
 * Strict reading of protocol messages: one JSON object, no duplicate keys, no unknown fields, every
 * value of its type and range. A problem is a {@link ProtocolException} naming the field.
 */
public final class Json {
    /** Shallow nesting: no protocol message needs more, so a deeply nested one is refused early. */
    private static final int MAX_DEPTH = 64;
    public static final ObjectMapper MAPPER = JsonMapper.builder(JsonFactory.builder()
                    .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH).build())
                    .build())
            .enable(DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .disable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
            .build();

    private Json() {
    }

    public static ObjectNode object() {
        return MAPPER.createObjectNode();
    }

    /** A message of this type. */
    public static ObjectNode message(String type) {
        return MAPPER.createObjectNode().put("type", type);
    }

    public static String write(JsonNode node) {
        try {
            return MAPPER.writeValueAsString(node);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("cannot write JSON", e);
        }
    }

    /** The message as a JSON object. */
    public static ObjectNode parse(String text) throws ProtocolException {
        JsonNode root;
        try {
            root = MAPPER.readTree(text);
        } catch (JsonProcessingException e) {
            String m = String.valueOf(e.getOriginalMessage()).lines().findFirst().orElse("");
            throw new ProtocolException("bad-message", "not valid JSON: " + (m.length() > 120 ? m.substring(0, 120) : m));
        }
        if (root == null || !root.isObject()) throw new ProtocolException("bad-message", "a message is one JSON object");
        return (ObjectNode) root;
    }

    public static void onlyFields(JsonNode node, List<String> allowed) throws ProtocolException {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!allowed.contains(f)) {
                throw bad(shown(f), "unknown field (expected " + String.join(", ", allowed) + ")");
            }
        }
    }

    public static JsonNode field(JsonNode node, String name) throws ProtocolException {
        JsonNode v = node.get(name);
        if (v == null || v.isNull()) throw bad(name, "is missing");
        return v;
    }

    public static String text(JsonNode node, String name, int maxChars) throws ProtocolException {
        JsonNode v = field(node, name);
        if (!v.isTextual()) throw bad(name, "must be a string");
        String s = v.textValue();
        if (s.length() > maxChars) throw bad(name, "is longer than " + maxChars + " characters");
        for (int i = 0; i < s.length(); i++) {
            if (Character.isISOControl(s.charAt(i))) throw bad(name, "must not hold control characters");
        }
        return s;
    }

    public static String matching(JsonNode node, String name, java.util.regex.Pattern pattern, String what)
            throws ProtocolException {
        String s = text(node, name, 200);
        if (!pattern.matcher(s).matches()) throw bad(name, "must be " + what);
        return s;
    }

    public static double number(JsonNode node, String name, double min, double max) throws ProtocolException {
        JsonNode v = field(node, name);
        if (!v.isNumber()) throw bad(name, "must be a number");
        double d = v.doubleValue();
        if (!(d >= min && d <= max)) throw bad(name, "must be " + min + " to " + max);
        return d;
    }

    public static long integer(JsonNode node, String name, long min, long max) throws ProtocolException {
        JsonNode v = field(node, name);
        if (!v.isIntegralNumber() || !v.canConvertToLong()) throw bad(name, "must be a whole number");
        long i = v.longValue();
        if (i < min || i > max) throw bad(name, "must be " + min + " to " + max);
        return i;
    }

    public static boolean bool(JsonNode node, String name) throws ProtocolException {
        JsonNode v = field(node, name);
        if (!v.isBoolean()) throw bad(name, "must be true or false");
        return v.booleanValue();
    }

    /** A finite number array of exactly {@code size}. */
    public static double[] numbers(JsonNode node, String name, int size) throws ProtocolException {
        JsonNode v = field(node, name);
        if (!v.isArray() || v.size() != size) throw bad(name, "must be an array of " + size + " numbers");
        double[] out = new double[size];
        for (int i = 0; i < size; i++) {
            JsonNode e = v.get(i);
            if (!e.isNumber() || !Double.isFinite(e.doubleValue())) throw bad(name + "[" + i + "]", "must be a finite number");
            out[i] = e.doubleValue();
        }
        return out;
    }

    public static ProtocolException bad(String field, String problem) {
        return new ProtocolException("bad-field", field + ": " + problem);
    }

    /** A value for a message: quoted, one line, cut short. */
    public static String shown(String value) {
        String v = value.length() > 40 ? value.substring(0, 37) + "..." : value;
        StringBuilder sb = new StringBuilder("\"");
        for (char c : v.toCharArray()) sb.append(Character.isISOControl(c) ? '?' : c);
        return sb.append('"').toString();
    }
}
