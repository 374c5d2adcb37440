package minigolf.course;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.Iterator;
import java.util.List;

/**
 * The checks every part of a course file's reader shares: a field's presence and type, numbers
 * that must be finite, positive or within [0, 1], points, and the one-line error naming the file,
 * the field's path and the problem.
 */
abstract class CourseJsonReader {
    final String source;

    CourseJsonReader(String source) {
        this.source = source;
    }

    CourseException error(String path, String problem) {
        return new CourseException(source, path, problem);
    }

    void minBelowMax(Vec2 min, Vec2 max, String path) throws CourseException {
        if (!(min.x() < max.x() && min.y() < max.y())) {
            throw error(path, "min must be < max in both axes, got min " + CourseValidator.point(min)
                    + ", max " + CourseValidator.point(max));
        }
    }

    double unit(double v, String path) throws CourseException {
        if (!(v >= 0 && v <= 1)) throw error(path, "must be between 0 and 1, got " + CourseValidator.number(v));
        return v;
    }

    Vec3 vec3(JsonNode n, String path) throws CourseException {
        if (!n.isArray() || n.size() != 3 || !n.get(0).isNumber() || !n.get(1).isNumber() || !n.get(2).isNumber()) {
            throw error(path, "expected [x, y, z], got " + show(n));
        }
        return new Vec3(number(n.get(0), path + "[0]"), number(n.get(1), path + "[1]"), number(n.get(2), path + "[2]"));
    }

    static String point3(Vec3 p) {
        return "(" + CourseValidator.number(p.x()) + ", " + CourseValidator.number(p.y()) + ", "
                + CourseValidator.number(p.z()) + ")";
    }

    ObjectNode object(JsonNode n, String path) throws CourseException {
        if (!n.isObject()) throw error(path, "expected an object, got " + kind(n));
        return (ObjectNode) n;
    }

    JsonNode required(ObjectNode o, String path, String field) throws CourseException {
        JsonNode n = o.get(field);
        if (n == null) throw error(join(path, field), "missing required field");
        return n;
    }

    void knownFields(ObjectNode o, String path, List<String> known) throws CourseException {
        for (Iterator<String> it = o.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!known.contains(f)) {
                throw error(join(path, f), "unknown field (known: " + String.join(", ", known) + ")");
            }
        }
    }

    String string(JsonNode n, String path) throws CourseException {
        if (!n.isTextual()) throw error(path, "expected a string, got " + kind(n));
        return n.textValue();
    }

    double number(JsonNode n, String path) throws CourseException {
        if (!n.isNumber()) throw error(path, "expected a number, got " + kind(n));
        double v = n.doubleValue();
        if (!Double.isFinite(v)) throw error(path, "must be a finite number, got " + n.asText());
        return v;
    }

    double positive(double v, String path) throws CourseException {
        if (!(v > 0)) throw error(path, "must be > 0, got " + CourseValidator.number(v));
        return v;
    }

    double nonNegative(double v, String path) throws CourseException {
        if (!(v >= 0)) throw error(path, "must be >= 0, got " + CourseValidator.number(v));
        return v;
    }

    Vec2 vec(JsonNode n, String path) throws CourseException {
        if (!n.isArray() || n.size() != 2 || !n.get(0).isNumber() || !n.get(1).isNumber()) {
            throw error(path, "expected [x, y], got " + show(n));
        }
        return new Vec2(number(n.get(0), path + "[0]"), number(n.get(1), path + "[1]"));
    }

    static String join(String path, String field) {
        return path.isEmpty() ? field : path + "." + field;
    }

    /** "a string", "an object", ... for "expected X, got Y". */
    static String kind(JsonNode n) {
        switch (n.getNodeType()) {
            case STRING: return "a string";
            case NUMBER: return "a number";
            case BOOLEAN: return "a boolean";
            case NULL: return "null";
            case ARRAY: return "an array";
            case OBJECT: return "an object";
            default: return n.getNodeType().toString().toLowerCase();
        }
    }

    /** The value as compact JSON, cut short when long: "star", [1,"a"]. */
    static String show(JsonNode n) {
        String s = n.toString();
        return s.length() > 60 ? s.substring(0, 57) + "..." : s;
    }

    /** A positive number, or {@code fallback} where the field is absent. */
    double optionalPositive(ObjectNode o, String path, String field, double fallback) throws CourseException {
        if (!o.has(field)) return fallback;
        String p = join(path, field);
        return positive(number(o.get(field), p), p);
    }
}
