package minigolf.course;

import java.util.List;

import static minigolf.course.CourseWriter.num;
import static minigolf.course.CourseWriter.require;
import static minigolf.course.CourseWriter.shape;
import static minigolf.course.CourseWriter.vec;
import static minigolf.course.CourseWriter.vec3;

/**
 * Writes a course's push zones, magnets and teleports and a moving obstacle's motion, in the
 * order and form of docs/course-format.md; each list only when it has entries.
 */
final class ElementWriter {
    private ElementWriter() {
    }

    /** The lists after {@code obstacles}, each followed by a comma but the last. */
    static void write(StringBuilder sb, Course course) {
        List<PushZone> pushes = course.pushZones();
        List<Magnet> magnets = course.magnets();
        List<Teleport> teleports = course.teleports();
        if (!pushes.isEmpty()) {
            sb.append("  \"pushZones\": [\n");
            for (int i = 0; i < pushes.size(); i++) {
                String path = "pushZones[" + i + "]";
                PushZone z = require(pushes.get(i), path);
                sb.append("    { \"shape\": ");
                shape(sb, require(z.shape(), path + ".shape"), path + ".shape");
                sb.append(", \"push\": ");
                vec(sb, require(z.push(), path + ".push"), path + ".push");
                sb.append(" }").append(i + 1 < pushes.size() ? ",\n" : "\n");
            }
            sb.append(magnets.isEmpty() && teleports.isEmpty() ? "  ]\n" : "  ],\n");
        }
        if (!magnets.isEmpty()) {
            sb.append("  \"magnets\": [\n");
            for (int i = 0; i < magnets.size(); i++) {
                String path = "magnets[" + i + "]";
                Magnet m = require(magnets.get(i), path);
                sb.append("    { \"position\": ");
                vec(sb, require(m.position(), path + ".position"), path + ".position");
                sb.append(", \"radius\": ").append(num(m.radius(), path + ".radius"))
                        .append(", \"strength\": ").append(num(m.strength(), path + ".strength"))
                        .append(" }").append(i + 1 < magnets.size() ? ",\n" : "\n");
            }
            sb.append(teleports.isEmpty() ? "  ]\n" : "  ],\n");
        }
        if (!teleports.isEmpty()) {
            sb.append("  \"teleports\": [\n");
            for (int i = 0; i < teleports.size(); i++) {
                String path = "teleports[" + i + "]";
                Teleport t = require(teleports.get(i), path);
                sb.append("    { \"entry\": ");
                shape(sb, require(t.entry(), path + ".entry"), path + ".entry");
                sb.append(", \"exits\": [");
                for (int k = 0; k < t.exits().size(); k++) {
                    String xp = path + ".exits[" + k + "]";
                    Teleport.Exit x = require(t.exits().get(k), xp);
                    sb.append(k > 0 ? ", " : "").append("{ \"position\": ");
                    vec(sb, require(x.position(), xp + ".position"), xp + ".position");
                    if (x.directionDeg() != null) sb.append(", \"directionDeg\": ").append(num(x.directionDeg(), xp + ".directionDeg"));
                    sb.append(" }");
                }
                sb.append("]");
                if (t.seed() != null) sb.append(", \"seed\": ").append(t.seed());
                sb.append(" }").append(i + 1 < teleports.size() ? ",\n" : "\n");
            }
            sb.append("  ]\n");
        }
    }

    /** A moving obstacle's motion object, every field written. */
    static void motion(StringBuilder sb, Motion motion, String path) {
        if (motion instanceof Motion.Rotate r) {
            sb.append("{ \"type\": \"rotate\", \"pivot\": ");
            vec3(sb, require(r.pivot(), path + ".pivot"), path + ".pivot");
            sb.append(", \"axis\": ");
            vec3(sb, require(r.axis(), path + ".axis"), path + ".axis");
        } else if (motion instanceof Motion.Swing w) {
            sb.append("{ \"type\": \"swing\", \"pivot\": ");
            vec3(sb, require(w.pivot(), path + ".pivot"), path + ".pivot");
            sb.append(", \"axis\": ");
            vec3(sb, require(w.axis(), path + ".axis"), path + ".axis");
            sb.append(", \"amplitudeDeg\": ").append(num(w.amplitudeDeg(), path + ".amplitudeDeg"));
        } else {
            Motion.Slide s = (Motion.Slide) motion;
            sb.append("{ \"type\": \"slide\", \"path\": [");
            for (int i = 0; i < s.path().size(); i++) {
                if (i > 0) sb.append(", ");
                vec3(sb, require(s.path().get(i), path + ".path"), path + ".path");
            }
            sb.append("], \"closed\": ").append(s.closed());
        }
        sb.append(", \"period\": ").append(num(motion.period(), path + ".period"))
                .append(", \"phase\": ").append(num(motion.phase(), path + ".phase")).append(" }");
    }
}
