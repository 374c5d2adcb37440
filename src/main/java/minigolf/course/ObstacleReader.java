package minigolf.course;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;

import static minigolf.course.CourseLoader.*;

/** Reads a course file's {@code zones} (friction areas and their shapes) and {@code obstacles} (walls, trees, boxes, models). */
final class ObstacleReader extends CourseJsonReader {
    private final ModelFiles models;

    ObstacleReader(String source, ModelFiles models) {
        super(source);
        this.models = models;
    }

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
            JsonNode h = o.get("hazard");
            Zone.Hazard hazard = h == null || h.isNull() ? null : hazard(h, join(zp, "hazard"));
            zones.add(new Zone(shape, kinetic, stat, hazard));
        }
        return zones;
    }

    Shape shape(JsonNode n, String path) throws CourseException {
        ObjectNode o = object(n, path);
        String tp = join(path, "type");
        JsonNode t = required(o, path, "type");
        String type = t.isTextual() ? t.textValue() : null;
        if (type == null || !(type.equals("rect") || type.equals("circle") || type.equals("polygon")
                || type.equals("cells"))) {
            throw error(tp, "expected one of rect, circle, polygon, cells, got " + show(t));
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
            case "cells" -> {
                return cells(o, path);
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

    /** A cells shape (docs/course-format.md): a grid of square cells, the cells given as row spans. */
    private Shape.Cells cells(ObjectNode o, String path) throws CourseException {
        knownFields(o, path, CELLS_FIELDS);
        Vec2 origin = vec(required(o, path, "origin"), join(path, "origin"));
        String sp = join(path, "size");
        double size = positive(number(required(o, path, "size"), sp), sp);
        int columns = count(required(o, path, "columns"), join(path, "columns"));
        int rows = count(required(o, path, "rows"), join(path, "rows"));
        if ((long) columns * rows > Limits.CELLS) {
            throw error(path, "too many cells: " + columns + " columns of " + rows + " rows = " + (long) columns * rows
                    + " (the limit is " + Limits.CELLS + ")");
        }
        String pp = join(path, "spans");
        JsonNode spans = required(o, path, "spans");
        if (!spans.isArray()) throw error(pp, "expected an array of [row, start, end] spans, got " + kind(spans));
        if (spans.size() > Limits.CELL_SPANS) {
            throw error(pp, "too many spans: " + spans.size() + " (the limit is " + Limits.CELL_SPANS + ")");
        }
        int[] triples = new int[3 * spans.size()];
        for (int i = 0; i < spans.size(); i++) {
            JsonNode s = spans.get(i);
            String ip = pp + "[" + i + "]";
            if (!s.isArray() || s.size() != 3) throw error(ip, "expected [row, start, end], got " + show(s));
            int row = index(s.get(0), ip + "[0]"), start = index(s.get(1), ip + "[1]"), end = index(s.get(2), ip + "[2]");
            if (row >= rows) throw error(ip, "row " + row + " is outside 0.." + (rows - 1));
            if (!(start < end) || end > columns) {
                throw error(ip, "columns " + start + ".." + end + " must satisfy start < end <= " + columns);
            }
            triples[3 * i] = row;
            triples[3 * i + 1] = start;
            triples[3 * i + 2] = end;
        }
        return new Shape.Cells(origin, size, columns, rows, triples);
    }

    private int count(JsonNode n, String path) throws CourseException {
        int v = index(n, path);
        if (v < 1) throw error(path, "must be a whole number >= 1, got " + v);
        return v;
    }

    /** A whole number from 0 to 2^31 - 1. */
    private int index(JsonNode n, String path) throws CourseException {
        if (n == null || !n.isIntegralNumber() || !n.canConvertToInt() || n.intValue() < 0) {
            throw error(path, "expected a whole number >= 0, got " + show(n));
        }
        return n.intValue();
    }

    private Zone.Hazard hazard(JsonNode n, String path) throws CourseException {
        ObjectNode o = object(n, path);
        knownFields(o, path, HAZARD_FIELDS);
        Zone.Hazard.Kind kind = named(o, path, "kind", Zone.Hazard.Kind.values(), Zone.Hazard.Kind.WATER);
        Zone.Hazard.When when = named(o, path, "when", Zone.Hazard.When.values(), Zone.Hazard.When.ENTER);
        Zone.Hazard.ReturnTo to = named(o, path, "returnTo", Zone.Hazard.ReturnTo.values(),
                Zone.Hazard.ReturnTo.STROKE_START);
        int penalty = 1;
        JsonNode p = o.get("penalty");
        if (p != null) {
            penalty = index(p, join(path, "penalty"));
            if (penalty > 1) throw error(join(path, "penalty"), "must be 0 or 1, got " + penalty);
        }
        return new Zone.Hazard(kind, when, to, penalty);
    }

    private <E extends Enum<E> & Zone.Hazard.Named> E named(ObjectNode o, String path, String field, E[] values, E fallback)
            throws CourseException {
        JsonNode n = o.get(field);
        if (n == null) return fallback;
        String fp = join(path, field);
        if (n.isTextual()) {
            for (E e : values) if (e.jsonName().equals(n.textValue())) return e;
        }
        StringBuilder names = new StringBuilder();
        for (E e : values) names.append(names.length() == 0 ? "" : ", ").append(e.jsonName());
        throw error(fp, "expected one of " + names + ", got " + show(n));
    }

    List<Obstacle> obstacles(JsonNode n, String path) throws CourseException {
        if (n == null) return List.of();
        if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
        if (n.size() > Limits.OBSTACLES) {
            throw error(path, "too many obstacles: " + n.size() + " (the limit is " + Limits.OBSTACLES + ")");
        }
        List<Obstacle> obstacles = new ArrayList<>(n.size());
        long triangles = 0;
        int moving = 0;
        for (int i = 0; i < n.size(); i++) {
            Obstacle obstacle = obstacle(n.get(i), path + "[" + i + "]");
            if (obstacle instanceof Obstacle.Moving && ++moving > Limits.MOVING_OBSTACLES) {
                throw error(path + "[" + i + "]", "too many moving obstacles: " + moving + " with this one (the limit is "
                        + Limits.MOVING_OBSTACLES + ")");
            }
            Obstacle body = obstacle instanceof Obstacle.Moving mo ? mo.body() : obstacle;
            if (body instanceof Obstacle.Model m) {
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
        Obstacle body = still(o, path);
        if (!o.has("motion")) return body;
        Motion motion = new MotionReader(source).motion(o.get("motion"), join(path, "motion"));
        MotionReader.checkReach(this, body, motion, join(path, "motion"));
        return new Obstacle.Moving(body, motion);
    }

    /** The obstacle as the file places it (a moving obstacle's body, its motion aside). */
    private Obstacle still(ObjectNode o, String path) throws CourseException {
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
                if (Limits.tooLong(file, Limits.FILE_NAME_CHARS) != null) throw error(fp, Limits.tooLong(file, Limits.FILE_NAME_CHARS));
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
            case "bumper" -> {
                knownFields(o, path, BUMPER_FIELDS);
                Vec2 position = vec(required(o, path, "position"), join(path, "position"));
                String rp = join(path, "radius");
                double radius = positive(number(required(o, path, "radius"), rp), rp);
                double height = optionalPositive(o, path, "height", BUMPER_HEIGHT);
                return new Obstacle.Bumper(position, radius, height,
                        restitution(o, path, Obstacle.DEFAULT_BUMPER_RESTITUTION));
            }
            case "gate" -> {
                knownFields(o, path, GATE_FIELDS);
                Vec2 from = vec(required(o, path, "from"), join(path, "from"));
                Vec2 to = vec(required(o, path, "to"), join(path, "to"));
                if (from.equals(to)) throw error(path, "from and to are the same point: the gate has no extent");
                String hp = join(path, "height");
                double height = positive(number(required(o, path, "height"), hp), hp);
                String sp = join(path, "passTo");
                JsonNode side = required(o, path, "passTo");
                Obstacle.Side passTo = side.isTextual() ? Obstacle.Side.fromJsonName(side.textValue()) : null;
                if (passTo == null) throw error(sp, "expected one of left, right, got " + show(side));
                return new Obstacle.Gate(from, to, height, passTo, restitution(o, path));
            }
            default -> throw error(join(path, "type"), "expected one of wall, tree, box, model, bumper, gate, got " + show(t));
        }
    }

    /** A bumper's height when the field is not given (m). */
    static final double BUMPER_HEIGHT = 0.1;

    private double restitution(ObjectNode o, String path) throws CourseException {
        return restitution(o, path, Obstacle.DEFAULT_RESTITUTION);
    }

    private double restitution(ObjectNode o, String path, double fallback) throws CourseException {
        if (!o.has("restitution")) return fallback;
        String p = join(path, "restitution");
        double v = number(o.get("restitution"), p);
        if (!(v >= 0 && v <= Obstacle.MAX_RESTITUTION)) {
            throw error(p, "must be between 0 and " + CourseValidator.number(Obstacle.MAX_RESTITUTION) + ", got "
                    + CourseValidator.number(v));
        }
        return v;
    }
}
