package minigolf.course;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;

import static minigolf.course.CourseLoader.EXIT_FIELDS;
import static minigolf.course.CourseLoader.MAGNET_FIELDS;
import static minigolf.course.CourseLoader.PUSH_ZONE_FIELDS;
import static minigolf.course.CourseLoader.TELEPORT_FIELDS;

/** Reads a course file's {@code pushZones}, {@code magnets} and {@code teleports} (docs/course-format.md). */
final class ElementReader extends CourseJsonReader {
    private final ObstacleReader shapes;

    ElementReader(String source, ObstacleReader shapes) {
        super(source);
        this.shapes = shapes;
    }

    List<PushZone> pushZones(JsonNode n, String path) throws CourseException {
        if (n == null) return List.of();
        if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
        if (n.size() > Limits.PUSH_ZONES) {
            throw error(path, "too many push zones: " + n.size() + " (the limit is " + Limits.PUSH_ZONES + ")");
        }
        checkPolygonPoints(n, path, "shape", "push zones");
        List<PushZone> zones = new ArrayList<>(n.size());
        for (int i = 0; i < n.size(); i++) {
            String zp = path + "[" + i + "]";
            ObjectNode o = object(n.get(i), zp);
            knownFields(o, zp, PUSH_ZONE_FIELDS);
            Shape shape = shapes.shape(required(o, zp, "shape"), join(zp, "shape"));
            String pp = join(zp, "push");
            Vec2 push = vec(required(o, zp, "push"), pp);
            double strength = Math.hypot(push.x(), push.y());
            if (strength > Limits.FORCE) {
                throw error(pp, "pushes with " + CourseValidator.approx(strength) + " m/s^2 (the limit is "
                        + CourseValidator.number(Limits.FORCE) + ")");
            }
            zones.add(new PushZone(shape, push));
        }
        return zones;
    }

    List<Magnet> magnets(JsonNode n, String path) throws CourseException {
        if (n == null) return List.of();
        if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
        if (n.size() > Limits.MAGNETS) {
            throw error(path, "too many magnets: " + n.size() + " (the limit is " + Limits.MAGNETS + ")");
        }
        List<Magnet> magnets = new ArrayList<>(n.size());
        for (int i = 0; i < n.size(); i++) {
            String mp = path + "[" + i + "]";
            ObjectNode o = object(n.get(i), mp);
            knownFields(o, mp, MAGNET_FIELDS);
            Vec2 position = vec(required(o, mp, "position"), join(mp, "position"));
            String rp = join(mp, "radius"), sp = join(mp, "strength");
            double radius = positive(number(required(o, mp, "radius"), rp), rp);
            double strength = number(required(o, mp, "strength"), sp);
            if (!(Math.abs(strength) <= Limits.FORCE)) {
                throw error(sp, "must be between -" + CourseValidator.number(Limits.FORCE) + " and "
                        + CourseValidator.number(Limits.FORCE) + " m/s^2, got " + CourseValidator.number(strength));
            }
            magnets.add(new Magnet(position, radius, strength));
        }
        return magnets;
    }

    List<Teleport> teleports(JsonNode n, String path) throws CourseException {
        if (n == null) return List.of();
        if (!n.isArray()) throw error(path, "expected an array, got " + kind(n));
        if (n.size() > Limits.TELEPORTS) {
            throw error(path, "too many teleports: " + n.size() + " (the limit is " + Limits.TELEPORTS + ")");
        }
        checkPolygonPoints(n, path, "entry", "teleport entries");
        List<Teleport> teleports = new ArrayList<>(n.size());
        for (int i = 0; i < n.size(); i++) {
            String tp = path + "[" + i + "]";
            ObjectNode o = object(n.get(i), tp);
            knownFields(o, tp, TELEPORT_FIELDS);
            Shape entry = shapes.shape(required(o, tp, "entry"), join(tp, "entry"));
            String ep = join(tp, "exits");
            JsonNode exits = required(o, tp, "exits");
            if (!exits.isArray()) throw error(ep, "expected an array, got " + kind(exits));
            if (exits.isEmpty()) throw error(ep, "a teleport needs at least one exit");
            if (exits.size() > Limits.TELEPORT_EXITS) {
                throw error(ep, "too many exits: " + exits.size() + " (the limit is " + Limits.TELEPORT_EXITS + ")");
            }
            List<Teleport.Exit> list = new ArrayList<>(exits.size());
            for (int k = 0; k < exits.size(); k++) {
                String xp = ep + "[" + k + "]";
                ObjectNode x = object(exits.get(k), xp);
                knownFields(x, xp, EXIT_FIELDS);
                Vec2 position = vec(required(x, xp, "position"), join(xp, "position"));
                Double direction = x.has("directionDeg") ? number(x.get("directionDeg"), join(xp, "directionDeg")) : null;
                list.add(new Teleport.Exit(position, direction));
            }
            Long seed = null;
            if (o.has("seed")) {
                JsonNode sn = o.get("seed");
                if (!sn.isIntegralNumber() || !sn.canConvertToLong()) {
                    throw error(join(tp, "seed"), "expected a whole number, got " + show(sn));
                }
                seed = sn.longValue();
            }
            teleports.add(new Teleport(entry, list, seed));
        }
        return teleports;
    }

    /** The polygon points of one list's shapes together, against {@link Limits#ALL_POLYGON_POINTS}. */
    private void checkPolygonPoints(JsonNode n, String path, String shapeField, String what) throws CourseException {
        int points = 0;
        for (JsonNode z : n) {
            JsonNode pts = z.path(shapeField).path("points");
            if (pts.isArray()) points += pts.size();
        }
        if (points > Limits.ALL_POLYGON_POINTS) {
            throw error(path, "too many polygon points in all " + what + ": " + points + " (the limit is "
                    + Limits.ALL_POLYGON_POINTS + ")");
        }
    }
}
