package minigolf.editor;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Motion;
import minigolf.course.Vec2;
import minigolf.course.Vec3;

/** A moving obstacle's motion carried along when the editor moves or turns the obstacle. Pure functions. */
public final class MotionTools {
    private MotionTools() {
    }

    /** The motion of an obstacle shifted by (dx, dy): its pivot moves with it (a slide's offsets do not change). */
    public static Motion moved(Motion m, double dx, double dy) {
        if (m instanceof Motion.Rotate r) {
            return new Motion.Rotate(shift(r.pivot(), dx, dy), r.axis(), r.period(), r.phase());
        }
        if (m instanceof Motion.Swing s) {
            return new Motion.Swing(shift(s.pivot(), dx, dy), s.axis(), s.amplitudeDeg(), s.period(), s.phase());
        }
        return m;
    }

    /** The motion of an obstacle turned by {@code degrees} about c: pivot, axis and path offsets turn with it. */
    public static Motion rotated(Motion m, Vec2 c, double degrees) {
        double a = Math.toRadians(degrees), cos = Math.cos(a), sin = Math.sin(a);
        if (m instanceof Motion.Rotate r) {
            return new Motion.Rotate(turnPoint(r.pivot(), c, cos, sin), turnVector(r.axis(), cos, sin), r.period(), r.phase());
        }
        if (m instanceof Motion.Swing s) {
            return new Motion.Swing(turnPoint(s.pivot(), c, cos, sin), turnVector(s.axis(), cos, sin), s.amplitudeDeg(),
                    s.period(), s.phase());
        }
        Motion.Slide s = (Motion.Slide) m;
        List<Vec3> path = new ArrayList<>();
        for (Vec3 p : s.path()) path.add(turnVector(p, cos, sin));
        return new Motion.Slide(path, s.period(), s.phase(), s.closed());
    }

    /** The same motion with another period and phase (s). */
    public static Motion withTiming(Motion m, double period, double phase) {
        if (m instanceof Motion.Rotate r) return new Motion.Rotate(r.pivot(), r.axis(), period, phase);
        if (m instanceof Motion.Swing s) return new Motion.Swing(s.pivot(), s.axis(), s.amplitudeDeg(), period, phase);
        Motion.Slide s = (Motion.Slide) m;
        return new Motion.Slide(s.path(), period, phase, s.closed());
    }

    private static Vec3 shift(Vec3 p, double dx, double dy) {
        return new Vec3(p.x() + dx, p.y() + dy, p.z());
    }

    private static Vec3 turnPoint(Vec3 p, Vec2 c, double cos, double sin) {
        double x = p.x() - c.x(), y = p.y() - c.y();
        return new Vec3(c.x() + cos * x - sin * y, c.y() + sin * x + cos * y, p.z());
    }

    private static Vec3 turnVector(Vec3 v, double cos, double sin) {
        return new Vec3(cos * v.x() - sin * v.y(), sin * v.x() + cos * v.y(), v.z());
    }
}
