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
import minigolf.expr.Expression;
import minigolf.expr.ExpressionException;
import minigolf.io.TextFiles;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.function.Function;

/**
 * Reads course files (format 1, see docs/course-format.md). The JSON is read into Jackson's tree
 * model and then checked by hand, field by field, so that every error is one line naming the file,
 * the field path and the problem, e.g. {@code courses/x.json: hole.radius: must be > 0, got -0.1}.
 * Nothing but {@link CourseException} ever leaves this class.
 *
 * <p>The start and the hole are always checked to lie inside the bounds. Whether they lie on dry
 * land needs the terrain's heights, which this package does not compute: pass a probe factory
 * (e.g. {@code spec -> terrainFor(spec)::height}, with the engine's terrain for the spec) to the overloads that take one; the overloads
 * without one skip the water check.
 */
public final class CourseLoader {
    static final List<String> TOP_FIELDS = List.of(
            "format", "name", "terrain", "bounds", "physics", "start", "hole", "zones", "obstacles");
    static final List<String> TERRAIN_FIELDS = List.of("height", "grid");
    static final List<String> GRID_FIELDS = List.of("origin", "spacing", "heights", "kineticFriction", "staticFriction",
            "deletedCells");
    static final List<String> BOUNDS_FIELDS = List.of("min", "max");
    static final List<String> PHYSICS_FIELDS = List.of("gravity", "kineticFriction", "staticFriction", "maxSpeed", "model",
            "ballRadius", "ballMass", "dragCoefficient", "airDensity", "groundRestitution");
    static final List<String> HOLE_FIELDS = List.of("position", "radius", "rule", "captureSpeed");
    static final List<String> ZONE_FIELDS = List.of("shape", "kineticFriction", "staticFriction");
    static final List<String> RECT_FIELDS = List.of("type", "min", "max");
    static final List<String> CIRCLE_FIELDS = List.of("type", "center", "radius");
    static final List<String> POLYGON_FIELDS = List.of("type", "points");
    static final List<String> WALL_FIELDS = List.of("type", "from", "to", "thickness", "height", "restitution");
    static final List<String> TREE_FIELDS = List.of("type", "position", "radius", "height", "restitution");
    static final List<String> BOX_FIELDS = List.of("type", "min", "max", "rotationDeg", "restitution");
    static final List<String> MODEL_FIELDS = List.of("type", "file", "position", "rotationDeg", "scale", "restitution");

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
            if (msg.startsWith("Duplicate field ")) {
                // Jackson: "Duplicate field 'name' for `ObjectNode`: not allowed when ..."
                int end = msg.indexOf(" for `");
                String what = end > 0 ? msg.substring("Duplicate field ".length(), end) : "";
                throw new CourseException(source, null, "not valid JSON" + where + ": duplicate field " + what, e);
            }
            throw new CourseException(source, null, "not valid JSON" + where + ": " + msg, e);
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
    private static final class Reader {
        private final String source;
        private final ModelFiles models;

        Reader(String source, ModelFiles models) {
            this.source = source;
            this.models = models;
        }

        private CourseException error(String path, String problem) {
            return new CourseException(source, path, problem);
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
            TerrainSpec terrain = terrain(required(o, "", "terrain"), "terrain");
            Bounds bounds = bounds(required(o, "", "bounds"), "bounds");
            PhysicsSettings physics = physics(required(o, "", "physics"), "physics");
            Vec2 start = vec(required(o, "", "start"), "start");
            Hole hole = hole(required(o, "", "hole"), "hole");
            List<Zone> zones = zones(o.get("zones"), "zones");
            List<Obstacle> obstacles = obstacles(o.get("obstacles"), "obstacles");
            return new Course(Course.FORMAT, name, terrain, bounds, physics, start, hole, zones, obstacles);
        }

        // ---- terrain ----

        TerrainSpec terrain(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, TERRAIN_FIELDS);
            boolean hasHeight = o.has("height"), hasGrid = o.has("grid");
            if (hasHeight == hasGrid) {
                throw error(path, "expected exactly one of height, grid, got " + (hasHeight ? "both" : "neither"));
            }
            if (hasHeight) {
                String p = join(path, "height");
                String src = string(o.get("height"), p);
                if (src.isBlank()) throw error(p, "must be a non-empty expression");
                try {
                    // Compiling checks the evaluation cost (the generated code must fit the JVM's limits).
                    Expression.parse(src).compile();
                } catch (ExpressionException e) {
                    String msg = String.valueOf(e.getMessage());
                    throw error(p, msg.contains("column") ? msg : msg + " at column " + e.column());
                } catch (RuntimeException e) {
                    throw error(p, "invalid expression: " + e.getMessage());
                }
                return new TerrainSpec.HeightExpression(src);
            }
            return grid(o.get("grid"), join(path, "grid"));
        }

        TerrainSpec.HeightGrid grid(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, GRID_FIELDS);
            Vec2 origin = vec(required(o, path, "origin"), join(path, "origin"));
            double spacing = positive(number(required(o, path, "spacing"), join(path, "spacing")), join(path, "spacing"));
            String hp = join(path, "heights");
            JsonNode hn = required(o, path, "heights");
            if (hn.isArray() && hn.size() > 0 && hn.get(0).isArray()) {
                long nodes = (long) hn.size() * hn.get(0).size();
                if (nodes > Limits.GRID_NODES) {
                    throw error(hp, "too many grid nodes: " + hn.size() + " rows of " + hn.get(0).size() + " = " + nodes
                            + " (the limit is " + Limits.GRID_NODES + ")");
                }
            }
            double[][] heights = matrix(required(o, path, "heights"), hp, -1, -1, false);
            if (heights.length < 2 || heights[0].length < 2) {
                throw error(hp, "must have at least 2 rows of at least 2 values (bicubic interpolation needs a 2x2 grid), got "
                        + heights.length + " row" + (heights.length == 1 ? "" : "s") + " of "
                        + (heights.length == 0 ? 0 : heights[0].length));
            }
            int rows = heights.length, cols = heights[0].length;
            double[][] kinetic = o.has("kineticFriction")
                    ? matrix(o.get("kineticFriction"), join(path, "kineticFriction"), rows, cols, true) : null;
            double[][] stat = o.has("staticFriction")
                    ? matrix(o.get("staticFriction"), join(path, "staticFriction"), rows, cols, true) : null;
            boolean[][] deleted = o.has("deletedCells")
                    ? deletedCells(o.get("deletedCells"), join(path, "deletedCells"), rows - 1, cols - 1) : null;
            return new TerrainSpec.HeightGrid(origin, spacing, heights, kinetic, stat, deleted);
        }

        /** {@code [[i, j], ...]}: the cells (column i, row j) removed from the course, each listed once. */
        boolean[][] deletedCells(JsonNode n, String path, int cellRows, int cellCols) throws CourseException {
            if (!n.isArray()) throw error(path, "expected an array of [i, j] cell indices, got " + kind(n));
            if ((long) n.size() > (long) cellRows * cellCols) {
                throw error(path, "lists " + n.size() + " cells but the grid has only " + (long) cellRows * cellCols);
            }
            boolean[][] mask = new boolean[cellRows][cellCols];
            for (int k = 0; k < n.size(); k++) {
                String cp = path + "[" + k + "]";
                JsonNode c = n.get(k);
                if (!c.isArray() || c.size() != 2) throw error(cp, "expected [i, j] (two integers), got "
                        + (c.isArray() ? "an array of " + c.size() : kind(c)));
                int i = cellIndex(c.get(0), cp + "[0]", cellCols, "columns");
                int j = cellIndex(c.get(1), cp + "[1]", cellRows, "rows");
                if (mask[j][i]) throw error(cp, "cell [" + i + ", " + j + "] is listed twice");
                mask[j][i] = true;
            }
            return mask;
        }

        private int cellIndex(JsonNode v, String path, int count, String what) throws CourseException {
            if (!v.isIntegralNumber()) throw error(path, "expected an integer cell index, got " + kind(v));
            long index = v.asLong();
            if (index < 0 || index >= count || !v.canConvertToInt()) {
                throw error(path, "cell index " + v.asText() + " is outside 0.." + (count - 1) + " (the grid has "
                        + count + " cell " + what + ")");
            }
            return (int) index;
        }

        /**
         * An array of equally long rows of numbers. With rows/cols &ge; 0 the shape must be exactly
         * that (the heights' shape); otherwise the first row sets the length.
         */
        double[][] matrix(JsonNode n, String path, int rows, int cols, boolean nonNegative) throws CourseException {
            if (!n.isArray()) throw error(path, "expected an array of rows, got " + kind(n));
            if (rows >= 0 && n.size() != rows) {
                throw error(path, "has " + n.size() + " rows, expected " + rows + " (the shape of heights)");
            }
            double[][] m = new double[n.size()][];
            int expected = cols;
            for (int j = 0; j < n.size(); j++) {
                String rp = path + "[" + j + "]";
                JsonNode row = n.get(j);
                if (!row.isArray()) throw error(rp, "expected a row (an array of numbers), got " + kind(row));
                if (expected < 0) expected = row.size();
                if (row.size() != expected) {
                    throw error(rp, "row has " + row.size() + " values, expected " + expected);
                }
                double[] r = new double[row.size()];
                for (int i = 0; i < r.length; i++) {
                    String vp = rp + "[" + i + "]";
                    r[i] = number(row.get(i), vp);
                    if (nonNegative) nonNegative(r[i], vp);
                }
                m[j] = r;
            }
            return m;
        }

        // ---- bounds, physics, hole ----

        Bounds bounds(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            knownFields(o, path, BOUNDS_FIELDS);
            Vec2 min = vec(required(o, path, "min"), join(path, "min"));
            Vec2 max = vec(required(o, path, "max"), join(path, "max"));
            minBelowMax(min, max, path);
            return new Bounds(min.x(), min.y(), max.x(), max.y());
        }

        private void minBelowMax(Vec2 min, Vec2 max, String path) throws CourseException {
            if (!(min.x() < max.x() && min.y() < max.y())) {
                throw error(path, "min must be < max in both axes, got min " + CourseValidator.point(min)
                        + ", max " + CourseValidator.point(max));
            }
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
            return new PhysicsSettings(gravity, kinetic, stat, maxSpeed, model, ballRadius, ballMass, drag, air, ground);
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

        // ---- zones, obstacles ----

        List<Zone> zones(JsonNode n, String path) throws CourseException {
            if (n == null) return List.of();
            if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
            if (n.size() > Limits.ZONES) throw error(path, "too many zones: " + n.size() + " (the limit is " + Limits.ZONES + ")");
            int points = 0;
            for (JsonNode z : n) {
                JsonNode pts = z.path("shape").path("points");
                if (pts.isArray()) points += pts.size();
            }
            if (points > Limits.ALL_POLYGON_POINTS) {
                throw error(path, "too many polygon points in all zones: " + points + " (the limit is "
                        + Limits.ALL_POLYGON_POINTS + ")");
            }
            List<Zone> zones = new ArrayList<>(n.size());
            for (int i = 0; i < n.size(); i++) {
                String zp = path + "[" + i + "]";
                ObjectNode o = object(n.get(i), zp);
                knownFields(o, zp, ZONE_FIELDS);
                Shape shape = shape(required(o, zp, "shape"), join(zp, "shape"));
                String kp = join(zp, "kineticFriction"), sp = join(zp, "staticFriction");
                double kinetic = nonNegative(number(required(o, zp, "kineticFriction"), kp), kp);
                double stat = nonNegative(number(required(o, zp, "staticFriction"), sp), sp);
                zones.add(new Zone(shape, kinetic, stat));
            }
            return zones;
        }

        Shape shape(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            String tp = join(path, "type");
            JsonNode t = required(o, path, "type");
            String type = t.isTextual() ? t.textValue() : null;
            if (type == null || !(type.equals("rect") || type.equals("circle") || type.equals("polygon"))) {
                throw error(tp, "expected one of rect, circle, polygon, got " + show(t));
            }
            switch (type) {
                case "rect" -> {
                    knownFields(o, path, RECT_FIELDS);
                    Vec2 min = vec(required(o, path, "min"), join(path, "min"));
                    Vec2 max = vec(required(o, path, "max"), join(path, "max"));
                    minBelowMax(min, max, path);
                    return new Shape.Rect(min, max);
                }
                case "circle" -> {
                    knownFields(o, path, CIRCLE_FIELDS);
                    Vec2 center = vec(required(o, path, "center"), join(path, "center"));
                    String rp = join(path, "radius");
                    return new Shape.Circle(center, positive(number(required(o, path, "radius"), rp), rp));
                }
                default -> {
                    knownFields(o, path, POLYGON_FIELDS);
                    String pp = join(path, "points");
                    JsonNode pts = required(o, path, "points");
                    if (!pts.isArray()) throw error(pp, "expected an array of [x, y] points, got " + kind(pts));
                    if (pts.size() < 3) throw error(pp, "a polygon needs at least 3 points, got " + pts.size());
                    if (pts.size() > Limits.POLYGON_POINTS) {
                        throw error(pp, "too many points: " + pts.size() + " (the limit is " + Limits.POLYGON_POINTS + ")");
                    }
                    List<Vec2> points = new ArrayList<>(pts.size());
                    for (int i = 0; i < pts.size(); i++) points.add(vec(pts.get(i), pp + "[" + i + "]"));
                    return new Shape.Polygon(points);
                }
            }
        }

        List<Obstacle> obstacles(JsonNode n, String path) throws CourseException {
            if (n == null) return List.of();
            if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
            if (n.size() > Limits.OBSTACLES) {
                throw error(path, "too many obstacles: " + n.size() + " (the limit is " + Limits.OBSTACLES + ")");
            }
            List<Obstacle> obstacles = new ArrayList<>(n.size());
            long triangles = 0;
            for (int i = 0; i < n.size(); i++) {
                Obstacle obstacle = obstacle(n.get(i), path + "[" + i + "]");
                if (obstacle instanceof Obstacle.Model m) {
                    triangles += m.mesh().triangleCount();
                    if (triangles > Limits.TRIANGLES) {
                        throw error(path + "[" + i + "]", "too many model triangles in all: " + triangles
                                + " with this one (the limit is " + Limits.TRIANGLES + ")");
                    }
                }
                obstacles.add(obstacle);
            }
            return obstacles;
        }

        Obstacle obstacle(JsonNode n, String path) throws CourseException {
            ObjectNode o = object(n, path);
            JsonNode t = required(o, path, "type");
            String type = t.isTextual() ? t.textValue() : "";
            switch (type) {
                case "wall" -> {
                    knownFields(o, path, WALL_FIELDS);
                    Vec2 from = vec(required(o, path, "from"), join(path, "from"));
                    Vec2 to = vec(required(o, path, "to"), join(path, "to"));
                    String tp = join(path, "thickness");
                    double thickness = nonNegative(number(required(o, path, "thickness"), tp), tp);
                    if (thickness == 0 && from.equals(to)) {
                        throw error(path, "from and to are the same point and thickness is 0: the wall has no extent");
                    }
                    String hp = join(path, "height");
                    double height = positive(number(required(o, path, "height"), hp), hp);
                    return new Obstacle.Wall(from, to, thickness, height, restitution(o, path));
                }
                case "tree" -> {
                    knownFields(o, path, TREE_FIELDS);
                    Vec2 position = vec(required(o, path, "position"), join(path, "position"));
                    String rp = join(path, "radius"), hp = join(path, "height");
                    double radius = positive(number(required(o, path, "radius"), rp), rp);
                    double height = positive(number(required(o, path, "height"), hp), hp);
                    return new Obstacle.Tree(position, radius, height, restitution(o, path));
                }
                case "box" -> {
                    knownFields(o, path, BOX_FIELDS);
                    Vec3 min = vec3(required(o, path, "min"), join(path, "min"));
                    Vec3 max = vec3(required(o, path, "max"), join(path, "max"));
                    if (!(min.x() < max.x() && min.y() < max.y() && min.z() < max.z())) {
                        throw error(path, "min must be < max in all three axes, got min " + point3(min) + ", max " + point3(max));
                    }
                    double rotation = o.has("rotationDeg") ? number(o.get("rotationDeg"), join(path, "rotationDeg")) : 0;
                    return new Obstacle.Box(min, max, rotation, restitution(o, path));
                }
                case "model" -> {
                    knownFields(o, path, MODEL_FIELDS);
                    String fp = join(path, "file");
                    String file = string(required(o, path, "file"), fp);
                    if (file.isBlank()) throw error(fp, "must be a non-empty file name");
                    Vec3 position = vec3(required(o, path, "position"), join(path, "position"));
                    double rotation = o.has("rotationDeg") ? number(o.get("rotationDeg"), join(path, "rotationDeg")) : 0;
                    double scale = optionalPositive(o, path, "scale", 1);
                    double restitution = restitution(o, path);
                    minigolf.mesh.TriangleMesh mesh;
                    try {
                        mesh = models.load(file);
                    } catch (ModelFiles.ModelException e) {
                        throw error(fp, e.getMessage());
                    }
                    return new Obstacle.Model(file, position, rotation, scale, restitution, mesh);
                }
                default -> throw error(join(path, "type"), "expected one of wall, tree, box, model, got " + show(t));
            }
        }

        private double restitution(ObjectNode o, String path) throws CourseException {
            if (!o.has("restitution")) return Obstacle.DEFAULT_RESTITUTION;
            String p = join(path, "restitution");
            return unit(number(o.get("restitution"), p), p);
        }

        private double optionalPositive(ObjectNode o, String path, String field, double fallback) throws CourseException {
            if (!o.has(field)) return fallback;
            String p = join(path, field);
            return positive(number(o.get(field), p), p);
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

        private static String point3(Vec3 p) {
            return "(" + CourseValidator.number(p.x()) + ", " + CourseValidator.number(p.y()) + ", "
                    + CourseValidator.number(p.z()) + ")";
        }

        // ---- primitives ----

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

        private static String join(String path, String field) {
            return path.isEmpty() ? field : path + "." + field;
        }

        /** "a string", "an object", ... for "expected X, got Y". */
        private static String kind(JsonNode n) {
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
        private static String show(JsonNode n) {
            String s = n.toString();
            return s.length() > 60 ? s.substring(0, 57) + "..." : s;
        }
    }
}
