package minigolf.game;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import minigolf.course.CourseException;
import minigolf.course.Limits;
import minigolf.io.ConfinedFiles;
import minigolf.io.JsonSyntax;
import minigolf.io.TextFiles;
import minigolf.physics.World;

/**
 * Reads round files (docs/course-format.md, "Round files"): {@code format}, {@code name} and
 * {@code holes}, each {@code {"course": FILE, "par": N}} with FILE relative to the round file's
 * folder. Every hole's course is loaded (start and hole checked for water), so a round that loads
 * can be played to the end. Errors are {@link CourseException}s of one line,
 * {@code <round file>: <field>: <problem>}; a broken course names the hole and the course's own error.
 */
public final class RoundLoader {
    public static final int FORMAT = 1;
    private static final List<String> TOP = List.of("format", "name", "holes");
    private static final List<String> HOLE = List.of("course", "par");

    private RoundLoader() {
    }

    /**
     * Loads a round file and every course it names. The courses must lie in the round's folder or a
     * folder beside it ({@link ConfinedFiles#roundCourse}): a round from someone else opens no other file.
     */
    public static Round load(Path file) throws CourseException {
        String source = String.valueOf(file);
        String json;
        try {
            json = TextFiles.read(file, Limits.ROUND_FILE_BYTES);
        } catch (TextFiles.TextFileException e) {
            throw new CourseException(source, null, "cannot read: " + e.getMessage());
        }
        Path folder = file.toAbsolutePath().getParent();
        return parse(json, source, course -> {
            Path path;
            try {
                path = ConfinedFiles.roundCourse(folder, course);
            } catch (TextFiles.TextFileException e) {
                throw new CourseException(course, null, e.getMessage());
            }
            return World.load(path);
        });
    }

    /** Loads a round packaged on the classpath, e.g. {@code /courses/rounds/meadowbrook-9.json}. */
    public static Round loadResource(String resource) throws CourseException {
        String json = readResource(resource, resource, null);
        String folder = resource.substring(0, resource.lastIndexOf('/') + 1);
        return parse(json, resource, course -> {
            String name = resourceCourse(folder, course);
            return World.parse(readResource(name, resource, course), name);
        });
    }

    /**
     * The classpath name of a bundled round's hole, as for files ({@link ConfinedFiles#roundCourse}):
     * in the round's folder ({@code /courses/rounds/}) or one beside it, nothing else on the classpath.
     */
    static String resourceCourse(String folder, String course) throws CourseException {
        String collection = folder.substring(0, Math.max(1, folder.lastIndexOf('/', folder.length() - 2) + 1));
        String name = Path.of(folder + course.replace('\\', '/')).normalize().toString().replace('\\', '/');
        if (course.startsWith("/") || course.startsWith("\\") || !name.startsWith(collection) || name.equals(collection)) {
            throw new CourseException(course, null, "refused: the path leaves the round's folder and the folders beside it");
        }
        return name;
    }

    /** How a hole's course file is turned into a world. */
    @FunctionalInterface
    public interface CourseSource {
        World load(String course) throws CourseException;
    }

    /** Parses round JSON; {@code courses} loads each hole's course (named as written in the file). */
    public static Round parse(String json, String source, CourseSource courses) throws CourseException {
        JsonNode root;
        try {
            root = JsonFields.MAPPER.readTree(json.startsWith("\uFEFF") ? json.substring(1) : json);
        } catch (JsonProcessingException e) {
            throw new CourseException(source, null, JsonSyntax.problem(e), e);
        }
        if (root == null || root.isMissingNode()) throw new CourseException(source, null, "not valid JSON: the file is empty");
        if (!root.isObject()) throw new CourseException(source, null, "expected a JSON object at the top level");
        onlyFields(root, null, TOP, source);
        JsonNode format = required(root, null, "format", source);
        if (!format.isIntegralNumber() || format.asInt() != FORMAT || !format.canConvertToInt()) {
            throw new CourseException(source, "format", "unsupported format " + format + " (this game reads round format " + FORMAT + ")");
        }
        JsonNode name = required(root, null, "name", source);
        if (!name.isTextual() || name.textValue().isBlank()) throw new CourseException(source, "name", "must be a non-empty string");
        String longName = Limits.tooLong(name.textValue(), Limits.NAME_CHARS);
        if (longName != null) throw new CourseException(source, "name", longName);
        JsonNode holesNode = required(root, null, "holes", source);
        if (!holesNode.isArray()) throw new CourseException(source, "holes", "expected an array of holes");
        if (holesNode.isEmpty() || holesNode.size() > Round.MAX_HOLES) {
            throw new CourseException(source, "holes", "a round has 1 to " + Round.MAX_HOLES + " holes, got " + holesNode.size());
        }
        List<Round.Hole> holes = new ArrayList<>();
        for (int i = 0; i < holesNode.size(); i++) {
            String path = "holes[" + i + "]";
            JsonNode h = holesNode.get(i);
            if (!h.isObject()) throw new CourseException(source, path, "expected {\"course\": FILE, \"par\": N}");
            onlyFields(h, path, HOLE, source);
            JsonNode course = required(h, path, "course", source);
            if (!course.isTextual() || course.textValue().isBlank()) {
                throw new CourseException(source, path + ".course", "must be a non-empty string (a course file)");
            }
            String longFile = Limits.tooLong(course.textValue(), Limits.FILE_NAME_CHARS);
            if (longFile != null) throw new CourseException(source, path + ".course", longFile);
            JsonNode par = required(h, path, "par", source);
            if (!par.isIntegralNumber() || !par.canConvertToInt() || par.asInt() < 1 || par.asInt() > Round.MAX_PAR) {
                throw new CourseException(source, path + ".par", "must be a whole number from 1 to " + Round.MAX_PAR + ", got " + par);
            }
            World world;
            try {
                world = courses.load(course.textValue());
            } catch (CourseException e) {
                throw new CourseException(source, path + ".course", e.getMessage(), e);
            }
            holes.add(new Round.Hole(course.textValue(), par.asInt(), world));
        }
        return new Round(name.textValue(), holes, source);
    }

    private static String readResource(String resource, String source, String asWritten) throws CourseException {
        try (InputStream in = RoundLoader.class.getResourceAsStream(resource)) {
            if (in == null) {
                if (asWritten == null) throw new CourseException(source, null, "cannot read: no such resource");
                throw new CourseException(resource, null, "cannot read: no such file in the game's resources");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new CourseException(resource, null, "cannot read: " + e.getMessage(), e);
        }
    }

    private static JsonNode required(JsonNode node, String path, String field, String source) throws CourseException {
        JsonNode v = node.get(field);
        if (v == null || v.isNull()) throw new CourseException(source, JsonFields.join(path, field), "missing required field");
        return v;
    }

    private static void onlyFields(JsonNode node, String path, List<String> known, String source) throws CourseException {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String f = it.next();
            if (!known.contains(f)) {
                throw new CourseException(source, JsonFields.join(path, f), "unknown field (known: " + String.join(", ", known) + ")");
            }
        }
    }
}
