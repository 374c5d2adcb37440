package minigolf.course;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;

import static minigolf.course.CourseLoader.ROTATE_FIELDS;
import static minigolf.course.CourseLoader.SLIDE_FIELDS;
import static minigolf.course.CourseLoader.SWING_FIELDS;

/** Reads a moving obstacle's {@code motion} (docs/course-format.md, "Moving obstacles"). */
final class MotionReader extends CourseJsonReader {
    MotionReader(String source) {
        super(source);
    }

    Motion motion(JsonNode n, String path) throws CourseException {
        ObjectNode o = object(n, path);
        JsonNode t = required(o, path, "type");
        String type = t.isTextual() ? t.textValue() : "";
        switch (type) {
            case "rotate" -> {
                knownFields(o, path, ROTATE_FIELDS);
                return new Motion.Rotate(vec3(required(o, path, "pivot"), join(path, "pivot")), axis(o, path),
                        period(o, path), phase(o, path));
            }
            case "swing" -> {
                knownFields(o, path, SWING_FIELDS);
                Vec3 pivot = vec3(required(o, path, "pivot"), join(path, "pivot"));
                Vec3 axis = axis(o, path);
                String ap = join(path, "amplitudeDeg");
                double amplitude = number(required(o, path, "amplitudeDeg"), ap);
                if (!(amplitude > 0 && amplitude <= 180)) {
                    throw error(ap, "must be more than 0 and at most 180, got " + CourseValidator.number(amplitude));
                }
                return new Motion.Swing(pivot, axis, amplitude, period(o, path), phase(o, path));
            }
            case "slide" -> {
                knownFields(o, path, SLIDE_FIELDS);
                String pp = join(path, "path");
                JsonNode points = required(o, path, "path");
                if (!points.isArray()) throw error(pp, "expected an array of [x, y, z] offsets, got " + kind(points));
                if (points.size() < 2) throw error(pp, "a path needs at least 2 points, got " + points.size());
                if (points.size() > Limits.PATH_POINTS) {
                    throw error(pp, "too many points: " + points.size() + " (the limit is " + Limits.PATH_POINTS + ")");
                }
                List<Vec3> path3 = new ArrayList<>(points.size());
                for (int i = 0; i < points.size(); i++) path3.add(vec3(points.get(i), pp + "[" + i + "]"));
                boolean closed = false;
                if (o.has("closed")) {
                    JsonNode c = o.get("closed");
                    if (!c.isBoolean()) throw error(join(path, "closed"), "expected true or false, got " + kind(c));
                    closed = c.booleanValue();
                }
                Motion.Slide slide = new Motion.Slide(path3, period(o, path), phase(o, path), closed);
                if (!(slide.travel() > 0)) throw error(pp, "the path has no length: every point is the same");
                double speed = slide.travel() / slide.period();
                if (speed > Limits.SLIDE_SPEED) {
                    throw error(path, "slides at " + CourseValidator.approx(speed) + " m/s (path length per period; the limit is "
                            + CourseValidator.number(Limits.SLIDE_SPEED) + " m/s)");
                }
                return slide;
            }
            default -> throw error(join(path, "type"), "expected one of rotate, swing, slide, got " + show(t));
        }
    }

    private Vec3 axis(ObjectNode o, String path) throws CourseException {
        if (!o.has("axis")) return new Vec3(0, 0, 1);
        String p = join(path, "axis");
        Vec3 a = vec3(o.get("axis"), p);
        double length = Math.sqrt(a.x() * a.x() + a.y() * a.y() + a.z() * a.z());
        if (!(length > 1e-9) || !Double.isFinite(length)) throw error(p, "must not be the zero vector");
        return a;
    }

    private double period(ObjectNode o, String path) throws CourseException {
        String p = join(path, "period");
        double v = number(required(o, path, "period"), p);
        if (!(v >= Limits.SHORTEST_PERIOD && v <= Limits.LONGEST_PERIOD)) {
            throw error(p, "must be between " + CourseValidator.number(Limits.SHORTEST_PERIOD) + " and "
                    + CourseValidator.number(Limits.LONGEST_PERIOD) + " s, got " + CourseValidator.number(v));
        }
        return v;
    }

    private double phase(ObjectNode o, String path) throws CourseException {
        return o.has("phase") ? number(o.get("phase"), join(path, "phase")) : 0;
    }

    /**
     * A turning or swinging body must stay within {@link Limits#MOTION_REACH} of its pivot
     * (horizontally, by its footprint), so no part of it moves absurdly fast.
     */
    static void checkReach(CourseJsonReader reader, Obstacle body, Motion motion, String path) throws CourseException {
        Vec3 pivot;
        if (motion instanceof Motion.Rotate r) pivot = r.pivot();
        else if (motion instanceof Motion.Swing s) pivot = s.pivot();
        else return;
        double reach = 0;
        for (Vec2 corner : footprint(body)) {
            reach = Math.max(reach, Math.hypot(corner.x() - pivot.x(), corner.y() - pivot.y()));
        }
        if (reach > Limits.MOTION_REACH) {
            throw reader.error(path, "the obstacle reaches " + CourseValidator.approx(reach) + " m from the pivot (the limit is "
                    + CourseValidator.number(Limits.MOTION_REACH) + " m)");
        }
    }

    /** Points whose convex hull covers the body's footprint in the plane. */
    private static List<Vec2> footprint(Obstacle body) {
        if (body instanceof Obstacle.Wall w) {
            double pad = w.thickness() / 2;
            return List.of(new Vec2(w.from().x() - pad, w.from().y() - pad), new Vec2(w.from().x() + pad, w.from().y() + pad),
                    new Vec2(w.to().x() - pad, w.to().y() - pad), new Vec2(w.to().x() + pad, w.to().y() + pad),
                    new Vec2(w.from().x() - pad, w.from().y() + pad), new Vec2(w.from().x() + pad, w.from().y() - pad),
                    new Vec2(w.to().x() - pad, w.to().y() + pad), new Vec2(w.to().x() + pad, w.to().y() - pad));
        }
        if (body instanceof Obstacle.Tree t) return square(t.position(), t.radius());
        if (body instanceof Obstacle.Bumper b) return square(b.position(), b.radius());
        if (body instanceof Obstacle.Box b) {
            // The box turns about its centre; its half diagonal bounds every turned corner.
            double cx = 0.5 * (b.min().x() + b.max().x()), cy = 0.5 * (b.min().y() + b.max().y());
            return square(new Vec2(cx, cy), Math.hypot(b.max().x() - cx, b.max().y() - cy));
        }
        Obstacle.Model m = (Obstacle.Model) body;
        if (m.mesh() == null) return List.of(new Vec2(m.position().x(), m.position().y()));
        float[] v = m.mesh().positions();
        double reach = 0;
        for (int i = 0; i + 2 < v.length; i += 3) reach = Math.max(reach, Math.hypot(v[i], v[i + 1]));
        return square(new Vec2(m.position().x(), m.position().y()), reach * m.scale());
    }

    private static List<Vec2> square(Vec2 c, double r) {
        return List.of(new Vec2(c.x() - r, c.y() - r), new Vec2(c.x() + r, c.y() - r), new Vec2(c.x() + r, c.y() + r),
                new Vec2(c.x() - r, c.y() + r));
    }
}
