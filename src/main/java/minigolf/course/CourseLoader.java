package minigolf.course;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import minigolf.io.JsonSyntax;
import minigolf.io.TextFiles;
import minigolf.theme.Themes;

import java.nio.charset.CharacterCodingException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;

/**
 * Reads course files (format 1, see docs/course-format.md). The JSON is read into Jackson's tree
 * model and then checked by hand, field by field, so that every error is one line naming the file,
 * the field path and the problem, e.g. {@code courses/x.json: hole.radius: must be > 0, got -0.1}.
 * Nothing but {@link CourseException} ever leaves this class. The sections are read by their own
 * readers ({@link TerrainReader}, {@link ObstacleReader}) on the checks they share ({@link CourseJsonReader}).
 *
 * <p>The start and the hole are always checked to lie inside the bounds. Whether they lie on dry
 * land needs the terrain's heights, which this package does not compute: pass a probe factory
 * (e.g. {@code spec -> terrainFor(spec)::height}, with the engine's terrain for the spec) to the overloads that take one; the overloads
 * without one skip the water check.
 */
public final class CourseLoader {
    static final List<String> TOP_FIELDS = List.of(
            "format", "name", "world", "terrain", "bounds", "physics", "start", "hole", "extraHoles", "zones", "obstacles",
            "pushZones", "magnets", "teleports", "bricks");
    static final List<String> TERRAIN_FIELDS = List.of("height", "grid");
    static final List<String> GRID_FIELDS = List.of("origin", "spacing", "heights", "kineticFriction", "staticFriction",
            "deletedCells");
    static final List<String> BOUNDS_FIELDS = List.of("min", "max");
    static final List<String> PHYSICS_FIELDS = List.of("gravity", "kineticFriction", "staticFriction", "maxSpeed", "model",
            "ballRadius", "ballMass", "dragCoefficient", "airDensity", "groundRestitution", "puttsOnly");
    static final List<String> HOLE_FIELDS = List.of("position", "radius", "rule", "captureSpeed");
    static final List<String> BRICK_FIELDS = List.of("min", "max", "hits", "restitution");
    static final List<String> ZONE_FIELDS = List.of("shape", "kineticFriction", "staticFriction", "hazard");
    static final List<String> HAZARD_FIELDS = List.of("kind", "when", "returnTo", "penalty");
    static final List<String> CELLS_FIELDS = List.of("type", "origin", "size", "columns", "rows", "spans");
    static final List<String> RECT_FIELDS = List.of("type", "min", "max");
    static final List<String> CIRCLE_FIELDS = List.of("type", "center", "radius");
    static final List<String> POLYGON_FIELDS = List.of("type", "points");
    static final List<String> WALL_FIELDS = List.of("type", "from", "to", "thickness", "height", "restitution", "motion");
    static final List<String> TREE_FIELDS = List.of("type", "position", "radius", "height", "restitution", "motion");
    static final List<String> BOX_FIELDS = List.of("type", "min", "max", "rotationDeg", "restitution", "motion");
    static final List<String> MODEL_FIELDS = List.of("type", "file", "position", "rotationDeg", "scale", "restitution",
            "motion");
    static final List<String> BUMPER_FIELDS = List.of("type", "position", "radius", "height", "restitution", "motion");
    static final List<String> GATE_FIELDS = List.of("type", "from", "to", "height", "passTo", "restitution");
    static final List<String> ROTATE_FIELDS = List.of("type", "pivot", "axis", "period", "phase");
    static final List<String> SWING_FIELDS = List.of("type", "pivot", "axis", "amplitudeDeg", "period", "phase");
    static final List<String> SLIDE_FIELDS = List.of("type", "path", "period", "phase", "closed");
    static final List<String> PUSH_ZONE_FIELDS = List.of("shape", "push");
    static final List<String> MAGNET_FIELDS = List.of("position", "radius", "strength");
    static final List<String> TELEPORT_FIELDS = List.of("entry", "exits", "seed");
    static final List<String> EXIT_FIELDS = List.of("position", "directionDeg");

    /** Strict JSON: no NaN/Infinity literals, no comments, no duplicate keys, nothing after the object. */
    private static final ObjectMapper MAPPER = JsonMapper.builder(JsonFactory.builder()
                    .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(Limits.JSON_DEPTH).build())
                    .build())
            .enable(DeserializationFeature.FAIL_ON_READING_DUP_TREE_KEY)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .disable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS)
            .disable(JsonReadFeature.ALLOW_JAVA_COMMENTS)
            .build();

    private CourseLoader() {
    }

    /** Reads and validates a course file; the water check of start and hole is skipped. */
    public static Course load(Path file) throws CourseException {
        return load(file, null);
    }

    /**
     * Reads and validates a course file. When {@code probes} is not null it is asked for the
     * heights of the course's terrain and the start and the hole are checked to be on dry land.
     */
    public static Course load(Path file, Function<TerrainSpec, HeightProbe> probes) throws CourseException {
        String source = String.valueOf(file);
        String json;
        try {
            json = TextFiles.read(file, Limits.COURSE_FILE_BYTES);
        } catch (TextFiles.TextFileException e) {
            throw new CourseException(source, null, "cannot read: " + e.getMessage());
        }
        return parse(json, source, probes, ModelFiles.beside(file));
    }

    /** Parses and validates course JSON; {@code sourceName} is used in error messages. No water check. */
    public static Course parse(String json, String sourceName) throws CourseException {
        return parse(json, sourceName, null);
    }

    /** Parses and validates course JSON; with a probe factory the start and hole are also checked for water. */
    public static Course parse(String json, String sourceName, Function<TerrainSpec, HeightProbe> probes)
            throws CourseException {
        return parse(json, sourceName, probes, ModelFiles.besideSource(sourceName));
    }

    /** As {@link #parse(String, String, Function)}, with the .obj files of model obstacles read through {@code models}. */
    static Course parse(String json, String sourceName, Function<TerrainSpec, HeightProbe> probes, ModelFiles models)
            throws CourseException {
        try {
            return parseChecked(json, sourceName, probes, models);
        } catch (OutOfMemoryError e) {
            // The limits should make this impossible; if a file still gets here, it is refused, not fatal.
            throw new CourseException(sourceName, null, "too large to load: the Java heap ran out of memory"
                    + " (limits: docs/course-format.md)");
        } catch (StackOverflowError e) {
            throw new CourseException(sourceName, null, "too deeply nested to load (limits: docs/course-format.md)");
        }
    }

    private static Course parseChecked(String json, String sourceName, Function<TerrainSpec, HeightProbe> probes,
                                       ModelFiles models) throws CourseException {
        if (json != null && json.length() > Limits.COURSE_FILE_BYTES) {
            throw new CourseException(sourceName, null, "too large: " + json.length() + " characters (the limit is "
                    + Limits.COURSE_FILE_BYTES + ")");
        }
        Course course = new Reader(sourceName, ModelFiles.cached(models)).course(readTree(json, sourceName));
        CourseValidator.checkInBounds(course, sourceName);
        if (probes != null) {
            HeightProbe probe;
            try {
                probe = probes.apply(course.terrain());
            } catch (RuntimeException e) {
                throw new CourseException(sourceName, "terrain", "cannot build the terrain: " + e.getMessage(), e);
            }
            if (probe == null) {
                throw new CourseException(sourceName, "terrain", "the probe factory gave no height probe for this terrain");
            }
            CourseValidator.checkPlacement(course, probe, sourceName);
        }
        return course;
    }

    private static JsonNode readTree(String json, String source) throws CourseException {
        if (json == null) throw new CourseException(source, null, "not valid JSON: no content");
        if (json.startsWith("\uFEFF")) json = json.substring(1);
        String blank = TextFiles.blankProblem(json);
        if (blank != null) throw new CourseException(source, null, "not valid JSON: " + blank);
        JsonNode root;
        try {
            root = MAPPER.readTree(json);
        } catch (com.fasterxml.jackson.core.exc.StreamConstraintsException e) {
            throw new CourseException(source, null, "not valid JSON: " + constraint(e));
        } catch (JsonProcessingException e) {
            String msg = firstLine(e.getOriginalMessage());
            JsonLocation loc = e.getLocation();
            String where = loc != null && loc.getLineNr() > 0
                    ? " at line " + loc.getLineNr() + ", column " + loc.getColumnNr() : "";
            if (msg.startsWith("Duplicate field ")) { // a field name of a file that is JSON: the file's own words are fine here
                // Jackson: "Duplicate field 'name' for `ObjectNode`: not allowed when ..."
                int end = msg.indexOf(" for `");
                String what = end > 0 ? msg.substring("Duplicate field ".length(), end) : "";
                throw new CourseException(source, null, "not valid JSON" + where + ": duplicate field " + what, e);
            }
            throw new CourseException(source, null, JsonSyntax.problem(e), e);
        } catch (RuntimeException e) {
            throw new CourseException(source, null, "not valid JSON: " + firstLine(String.valueOf(e.getMessage())), e);
        }
        if (root == null || root.isMissingNode()) {
            throw new CourseException(source, null, "not valid JSON: the file is empty");
        }
        return root;
    }

    /** Jackson's limits in our words: "nested more than 32 levels deep (the limit)". */
    static String constraint(com.fasterxml.jackson.core.exc.StreamConstraintsException e) {
        String m = String.valueOf(e.getOriginalMessage());
        if (m.contains("nesting depth")) return "nested more than " + Limits.JSON_DEPTH + " levels deep (the limit)";
        return firstLine(m);
    }

    private static String firstLine(String s) {
        if (s == null) return "";
        int nl = s.indexOf('\n');
        return (nl >= 0 ? s.substring(0, nl) : s).trim();
    }

    static String describe(Exception e, Path target) {
        if (e instanceof NoSuchFileException f) {
            return sameFile(f.getFile(), target) ? "no such file" : "no such file or directory: " + f.getFile();
        }
        if (e instanceof AccessDeniedException f) {
            return sameFile(f.getFile(), target) ? "permission denied" : "permission denied: " + f.getFile();
        }
        if (e instanceof CharacterCodingException) {
            return "not valid UTF-8 text";
        }
        if (e instanceof FileSystemException f && f.getReason() != null) {
            return sameFile(f.getFile(), target) ? f.getReason() : f.getReason() + ": " + f.getFile();
        }
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : firstLine(m);
    }

    private static boolean sameFile(String name, Path target) {
        return name == null || target == null || name.equals(target.toString())
                || name.equals(target.toAbsolutePath().toString());
    }

    /** Walks the tree; every method gets the field path of the node it reads. */
    private static final class Reader extends CourseJsonReader {
        private final TerrainReader terrainReader;
        private final ObstacleReader obstacleReader;

        Reader(String source, ModelFiles models) {
            super(source);
            terrainReader = new TerrainReader(source);
            obstacleReader = new ObstacleReader(source, models);
        }

        Course course(JsonNode root) throws CourseException {
            if (!root.isObject()) {
                throw error(null, "expected a JSON object at the top level, got " + kind(root));
            }
            ObjectNode o = (ObjectNode) root;
            // The format first: a file from a newer engine may well have fields this one does not know.
            JsonNode f = required(o, "", "format");
            if (!f.isNumber()) throw error("format", "expected a number, got " + kind(f));
            if (!f.isIntegralNumber() || f.asLong() != Course.FORMAT || !f.canConvertToInt()) {
                throw error("format", "unsupported format " + f + " (this engine reads format " + Course.FORMAT + ")");
            }
            knownFields(o, "", TOP_FIELDS);
            String name = string(required(o, "", "name"), "name");
            if (name.isBlank()) throw error("name", "must be a non-empty string");
            if (Limits.tooLong(name, Limits.NAME_CHARS) != null) throw error("name", Limits.tooLong(name, Limits.NAME_CHARS));
            String world = o.has("world") ? string(o.get("world"), "world") : Themes.DEFAULT_ID;
            if (Themes.byId(world) == null) {
                throw error("world", "expected one of " + String.join(", ", Themes.ids()) + ", got " + show(o.get("world")));
            }
            TerrainSpec terrain = terrainReader.terrain(required(o, "", "terrain"), "terrain");
            Bounds bounds = bounds(required(o, "", "bounds"), "bounds");
            PhysicsSettings physics = physics(required(o, "", "physics"), "physics");
            Vec2 start = vec(required(o, "", "start"), "start");
            Hole hole = hole(required(o, "", "hole"), "hole");
            List<Hole> extraHoles = extraHoles(o.get("extraHoles"), "extraHoles");
            List<Zone> zones = obstacleReader.zones(o.get("zones"), "zones");
            List<Obstacle> obstacles = obstacleReader.obstacles(o.get("obstacles"), "obstacles");
            ElementReader elements = new ElementReader(source, obstacleReader);
            List<PushZone> pushZones = elements.pushZones(o.get("pushZones"), "pushZones");
            List<Magnet> magnets = elements.magnets(o.get("magnets"), "magnets");
            List<Teleport> teleports = elements.teleports(o.get("teleports"), "teleports");
            List<Brick> bricks = bricks(o.get("bricks"), "bricks");
            return new Course(Course.FORMAT, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones,
                    magnets, teleports, world, extraHoles, bricks);
        }

        // ---- terrain ----

        // ---- bounds, physics, hole ----

        Bounds bounds(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, BOUNDS_FIELDS);
            Vec2 min = vec(required(o, path, "min"), join(path, "min"));
            Vec2 max = vec(required(o, path, "max"), join(path, "max"));
            minBelowMax(min, max, path);
            return new Bounds(min.x(), min.y(), max.x(), max.y());
        }

        PhysicsSettings physics(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, PHYSICS_FIELDS);
            double gravity = o.has("gravity")
                    ? positive(number(o.get("gravity"), join(path, "gravity")), join(path, "gravity"))
                    : PhysicsSettings.DEFAULT_GRAVITY;
            double kinetic = nonNegative(number(required(o, path, "kineticFriction"), join(path, "kineticFriction")),
                    join(path, "kineticFriction"));
            double stat = nonNegative(number(required(o, path, "staticFriction"), join(path, "staticFriction")),
                    join(path, "staticFriction"));
            double maxSpeed = o.has("maxSpeed")
                    ? positive(number(o.get("maxSpeed"), join(path, "maxSpeed")), join(path, "maxSpeed"))
                    : PhysicsSettings.DEFAULT_MAX_SPEED;
            PhysicsModel model = PhysicsModel.CLASSIC;
            if (o.has("model")) {
                String p = join(path, "model");
                JsonNode m = o.get("model");
                model = m.isTextual() ? PhysicsModel.fromJsonName(m.textValue()) : null;
                if (model == null) throw error(p, "expected one of classic, complete, got " + show(m));
            }
            double ballRadius = optionalPositive(o, path, "ballRadius", PhysicsSettings.DEFAULT_BALL_RADIUS);
            double ballMass = optionalPositive(o, path, "ballMass", PhysicsSettings.DEFAULT_BALL_MASS);
            double drag = o.has("dragCoefficient")
                    ? nonNegative(number(o.get("dragCoefficient"), join(path, "dragCoefficient")), join(path, "dragCoefficient"))
                    : PhysicsSettings.DEFAULT_DRAG_COEFFICIENT;
            double air = o.has("airDensity")
                    ? nonNegative(number(o.get("airDensity"), join(path, "airDensity")), join(path, "airDensity"))
                    : PhysicsSettings.DEFAULT_AIR_DENSITY;
            Double ground = o.has("groundRestitution")
                    ? unit(number(o.get("groundRestitution"), join(path, "groundRestitution")), join(path, "groundRestitution"))
                    : null;
            boolean puttsOnly = false;
            if (o.has("puttsOnly")) {
                JsonNode b = o.get("puttsOnly");
                if (!b.isBoolean()) throw error(join(path, "puttsOnly"), "expected true or false, got " + show(b));
                puttsOnly = b.booleanValue();
            }
            return new PhysicsSettings(gravity, kinetic, stat, maxSpeed, model, ballRadius, ballMass, drag, air, ground,
                    puttsOnly);
        }

        Hole hole(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, HOLE_FIELDS);
            Vec2 position = vec(required(o, path, "position"), join(path, "position"));
            String rp = join(path, "radius");
            double radius = positive(number(required(o, path, "radius"), rp), rp);
            HoleRule rule = HoleRule.REST;
            if (o.has("rule")) {
                JsonNode r = o.get("rule");
                rule = r.isTextual() ? HoleRule.fromJsonName(r.textValue()) : null;
                if (rule == null) throw error(join(path, "rule"), "expected one of rest, capture, got " + show(r));
            }
            Double capture = null;
            if (o.has("captureSpeed")) {
                String cp = join(path, "captureSpeed");
                capture = positive(number(o.get("captureSpeed"), cp), cp);
            }
            return new Hole(position, radius, rule, capture);
        }

        List<Hole> extraHoles(JsonNode n, String path) throws CourseException {
            if (n == null) return List.of();
            if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
            if (n.size() > Limits.EXTRA_HOLES) {
                throw error(path, "too many holes: " + n.size() + " (the limit is " + Limits.EXTRA_HOLES + ")");
            }
            List<Hole> holes = new ArrayList<>(n.size());
            for (int i = 0; i < n.size(); i++) holes.add(hole(n.get(i), path + "[" + i + "]"));
            return holes;
        }

        List<Brick> bricks(JsonNode n, String path) throws CourseException {
            if (n == null) return List.of();
            if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
            if (n.size() > Limits.BRICKS) {
                throw error(path, "too many bricks: " + n.size() + " (the limit is " + Limits.BRICKS + ")");
            }
            List<Brick> bricks = new ArrayList<>(n.size());
            for (int i = 0; i < n.size(); i++) bricks.add(brick(n.get(i), path + "[" + i + "]"));
            return bricks;
        }

        Brick brick(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, BRICK_FIELDS);
            Vec3 min = vec3(required(o, path, "min"), join(path, "min"));
            Vec3 max = vec3(required(o, path, "max"), join(path, "max"));
            if (!(min.x() < max.x() && min.y() < max.y() && min.z() < max.z())) {
                throw error(path, "min must be < max in all three axes, got min " + point3(min) + ", max " + point3(max));
            }
            String hp = join(path, "hits");
            JsonNode h = required(o, path, "hits");
            if (!h.isIntegralNumber() || !h.canConvertToInt() || h.intValue() < 1 || h.intValue() > Brick.MAX_HITS) {
                throw error(hp, "expected a whole number from 1 to " + Brick.MAX_HITS + ", got " + show(h));
            }
            double restitution = Brick.DEFAULT_RESTITUTION;
            if (o.has("restitution")) {
                String rp = join(path, "restitution");
                restitution = number(o.get("restitution"), rp);
                if (!(restitution >= 0 && restitution <= 1)) {
                    throw error(rp, "must be between 0 and 1, got " + CourseValidator.number(restitution));
                }
            }
            return new Brick(min, max, h.intValue(), restitution);
        }

        // ---- zones, obstacles ----

        // ---- primitives ----

    }
}
