package minigolf.course;

import minigolf.theme.Themes;

import com.fasterxml.jackson.core.io.JsonStringEncoder;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import minigolf.io.AtomicFile;

/**
 * Writes courses in the course-file format (format 1), fields in the documented order, so that
 * {@code CourseLoader.parse(CourseWriter.toJson(c), ...)} equals {@code c} exactly: every double is
 * written in Java's round-trip representation and read back to the same bits.
 */
public final class CourseWriter {
    private CourseWriter() {
    }

    /**
     * The course as pretty-printed JSON (ending in a newline).
     *
     * @throws IllegalArgumentException if a number is NaN or infinite, or a component is missing
     */
    public static String toJson(Course course) {
        StringBuilder sb = new StringBuilder(4096);
        sb.append("{\n");
        sb.append("  \"format\": ").append(course.format()).append(",\n");
        sb.append("  \"name\": ").append(quote(require(course.name(), "name"))).append(",\n");
        // The world only where it is not the default: older files stay as they were.
        if (!Themes.DEFAULT_ID.equals(course.world())) sb.append("  \"world\": ").append(quote(course.world())).append(",\n");
        sb.append("  \"terrain\": ");
        terrain(sb, require(course.terrain(), "terrain"));
        sb.append(",\n");
        Bounds b = require(course.bounds(), "bounds");
        sb.append("  \"bounds\": { \"min\": ");
        vec(sb, b.minX(), b.minY(), "bounds.min");
        sb.append(", \"max\": ");
        vec(sb, b.maxX(), b.maxY(), "bounds.max");
        sb.append(" },\n");
        PhysicsSettings p = require(course.physics(), "physics");
        sb.append("  \"physics\": { \"gravity\": ").append(num(p.gravity(), "physics.gravity"))
                .append(", \"kineticFriction\": ").append(num(p.kineticFriction(), "physics.kineticFriction"))
                .append(", \"staticFriction\": ").append(num(p.staticFriction(), "physics.staticFriction"))
                .append(", \"maxSpeed\": ").append(num(p.maxSpeed(), "physics.maxSpeed"))
                .append(", \"model\": ").append(quote(require(p.model(), "physics.model").jsonName()));
        // The ball and flight fields only where they differ from the defaults: old files stay as they were.
        optional(sb, "ballRadius", p.ballRadius(), PhysicsSettings.DEFAULT_BALL_RADIUS);
        optional(sb, "ballMass", p.ballMass(), PhysicsSettings.DEFAULT_BALL_MASS);
        optional(sb, "dragCoefficient", p.dragCoefficient(), PhysicsSettings.DEFAULT_DRAG_COEFFICIENT);
        optional(sb, "airDensity", p.airDensity(), PhysicsSettings.DEFAULT_AIR_DENSITY);
        if (p.groundRestitution() != null) {
            sb.append(", \"groundRestitution\": ").append(num(p.groundRestitution(), "physics.groundRestitution"));
        }
        if (p.puttsOnly()) sb.append(", \"puttsOnly\": true");
        sb.append(" },\n");
        sb.append("  \"start\": ");
        vec(sb, require(course.start(), "start"), "start");
        sb.append(",\n");
        sb.append("  \"hole\": ");
        hole(sb, require(course.hole(), "hole"), "hole");
        sb.append(",\n");
        List<Hole> extra = course.extraHoles();
        if (!extra.isEmpty()) {
            sb.append("  \"extraHoles\": [\n");
            for (int i = 0; i < extra.size(); i++) {
                sb.append("    ");
                hole(sb, require(extra.get(i), "extraHoles[" + i + "]"), "extraHoles[" + i + "]");
                sb.append(i + 1 < extra.size() ? ",\n" : "\n");
            }
            sb.append("  ],\n");
        }
        List<Brick> bricks = course.bricks();
        if (!bricks.isEmpty()) {
            sb.append("  \"bricks\": [\n");
            for (int i = 0; i < bricks.size(); i++) {
                String bp = "bricks[" + i + "]";
                Brick brick = require(bricks.get(i), bp);
                sb.append("    { \"min\": ");
                vec3(sb, require(brick.min(), bp + ".min"), bp + ".min");
                sb.append(", \"max\": ");
                vec3(sb, require(brick.max(), bp + ".max"), bp + ".max");
                sb.append(", \"hits\": ").append(brick.hits());
                if (brick.restitution() != Brick.DEFAULT_RESTITUTION) {
                    sb.append(", \"restitution\": ").append(num(brick.restitution(), bp + ".restitution"));
                }
                sb.append(" }").append(i + 1 < bricks.size() ? ",\n" : "\n");
            }
            sb.append("  ],\n");
        }
        List<Zone> zones = course.zones();
        if (zones.isEmpty()) {
            sb.append("  \"zones\": [],\n");
        } else {
            sb.append("  \"zones\": [\n");
            for (int i = 0; i < zones.size(); i++) {
                String zp = "zones[" + i + "]";
                Zone z = zones.get(i);
                sb.append("    { \"shape\": ");
                shape(sb, require(z.shape(), zp + ".shape"), zp + ".shape");
                sb.append(", \"kineticFriction\": ").append(num(z.kineticFriction(), zp + ".kineticFriction"))
                        .append(", \"staticFriction\": ").append(num(z.staticFriction(), zp + ".staticFriction"));
                if (z.hazard() != null) {
                    Zone.Hazard hz = z.hazard();
                    sb.append(", \"hazard\": { \"kind\": \"").append(hz.kind().jsonName())
                            .append("\", \"when\": \"").append(hz.when().jsonName())
                            .append("\", \"returnTo\": \"").append(hz.returnTo().jsonName())
                            .append("\", \"penalty\": ").append(hz.penalty()).append(" }");
                }
                sb.append(" }").append(i + 1 < zones.size() ? ",\n" : "\n");
            }
            sb.append("  ],\n");
        }
        List<Obstacle> obstacles = course.obstacles();
        // The newer lists only when they have entries, so files without them are written back as they were.
        boolean more = !course.pushZones().isEmpty() || !course.magnets().isEmpty() || !course.teleports().isEmpty();
        if (obstacles.isEmpty()) {
            sb.append("  \"obstacles\": []").append(more ? ",\n" : "\n");
        } else {
            sb.append("  \"obstacles\": [\n");
            for (int i = 0; i < obstacles.size(); i++) {
                sb.append("    ");
                obstacle(sb, require(obstacles.get(i), "obstacles[" + i + "]"), "obstacles[" + i + "]");
                sb.append(i + 1 < obstacles.size() ? ",\n" : "\n");
            }
            sb.append(more ? "  ],\n" : "  ]\n");
        }
        ElementWriter.write(sb, course);
        sb.append("}\n");
        return sb.toString();
    }

    /**
     * Saves the course atomically: the JSON goes to a temporary file in the same directory, is
     * forced to disk and then moved over {@code file} (an atomic rename where the file system has
     * one). If anything fails the previous file is left as it was and the temporary file removed.
     * A course that would not load again (e.g. a negative hole radius) is not written.
     */
    public static void save(Course course, Path file) throws CourseException {
        String source = String.valueOf(file);
        String json;
        try {
            json = toJson(course);
        } catch (RuntimeException e) {
            throw new CourseException(source, null, "cannot save: " + e.getMessage(), e);
        }
        try {
            // Model files are checked as the course holds them: the target folder need not have them yet.
            java.util.Map<String, minigolf.mesh.TriangleMesh> meshes = new java.util.HashMap<>();
            for (Obstacle o : course.obstacles()) {
                if (o instanceof Obstacle.Model m && m.mesh() != null) meshes.put(m.file(), m.mesh());
            }
            CourseLoader.parse(json, source, null, ModelFiles.known(meshes, ModelFiles.beside(file)));
        } catch (CourseException e) {
            throw new CourseException(source, null, "cannot save: " + e.detail(), e);
        }
        try {
            AtomicFile.write(file, json.getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new CourseException(source, null, "cannot save: " + e.getMessage(), e);
        }
    }

    // ---- pieces ----

    private static void terrain(StringBuilder sb, TerrainSpec t) {
        if (t instanceof TerrainSpec.HeightExpression e) {
            sb.append("{ \"height\": ").append(quote(require(e.source(), "terrain.height"))).append(" }");
            return;
        }
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) t;
        sb.append("{\n    \"grid\": {\n      \"origin\": ");
        vec(sb, require(g.origin(), "terrain.grid.origin"), "terrain.grid.origin");
        sb.append(",\n      \"spacing\": ").append(num(g.spacing(), "terrain.grid.spacing"));
        sb.append(",\n      \"heights\": ");
        matrix(sb, require(g.heights(), "terrain.grid.heights"), "terrain.grid.heights");
        if (g.kineticFriction() != null) {
            sb.append(",\n      \"kineticFriction\": ");
            matrix(sb, g.kineticFriction(), "terrain.grid.kineticFriction");
        }
        if (g.staticFriction() != null) {
            sb.append(",\n      \"staticFriction\": ");
            matrix(sb, g.staticFriction(), "terrain.grid.staticFriction");
        }
        int deletedCount = g.deletedCount();
        if (deletedCount > 0) {
            sb.append(",\n      \"deletedCells\": [");
            int written = 0;
            for (int j = 0; j < g.deleted().length; j++) {
                for (int i = 0; i < g.deleted()[j].length; i++) {
                    if (!g.deleted()[j][i]) continue;
                    sb.append(written % 16 == 0 ? "\n        " : " ").append('[').append(i).append(", ").append(j).append(']');
                    if (++written < deletedCount) sb.append(',');
                }
            }
            sb.append("\n      ]");
        }
        sb.append("\n    }\n  }");
    }

    /** One row per line. */
    private static void matrix(StringBuilder sb, double[][] m, String path) {
        sb.append("[\n");
        for (int j = 0; j < m.length; j++) {
            double[] row = require(m[j], path + "[" + j + "]");
            sb.append("        [");
            for (int i = 0; i < row.length; i++) {
                if (i > 0) sb.append(", ");
                sb.append(num(row[i], path));
            }
            sb.append(j + 1 < m.length ? "],\n" : "]\n");
        }
        sb.append("      ]");
    }

    static void shape(StringBuilder sb, Shape s, String path) {
        if (s instanceof Shape.Rect r) {
            sb.append("{ \"type\": \"rect\", \"min\": ");
            vec(sb, require(r.min(), path + ".min"), path + ".min");
            sb.append(", \"max\": ");
            vec(sb, require(r.max(), path + ".max"), path + ".max");
            sb.append(" }");
        } else if (s instanceof Shape.Circle c) {
            sb.append("{ \"type\": \"circle\", \"center\": ");
            vec(sb, require(c.center(), path + ".center"), path + ".center");
            sb.append(", \"radius\": ").append(num(c.radius(), path + ".radius")).append(" }");
        } else if (s instanceof Shape.Cells c) {
            sb.append("{ \"type\": \"cells\", \"origin\": ");
            vec(sb, require(c.origin(), path + ".origin"), path + ".origin");
            sb.append(", \"size\": ").append(num(c.size(), path + ".size"))
                    .append(", \"columns\": ").append(c.columns()).append(", \"rows\": ").append(c.rows())
                    .append(", \"spans\": [");
            int[] spans = c.spans();
            for (int i = 0; i < spans.length; i += 3) {
                if (i > 0) sb.append(", ");
                sb.append('[').append(spans[i]).append(", ").append(spans[i + 1]).append(", ").append(spans[i + 2]).append(']');
            }
            sb.append("] }");
        } else {
            Shape.Polygon p = (Shape.Polygon) s;
            sb.append("{ \"type\": \"polygon\", \"points\": [");
            for (int i = 0; i < p.points().size(); i++) {
                if (i > 0) sb.append(", ");
                vec(sb, require(p.points().get(i), path + ".points"), path + ".points");
            }
            sb.append("] }");
        }
    }

    private static void optional(StringBuilder sb, String field, double value, double fallback) {
        if (Double.compare(value, fallback) != 0) sb.append(", \"").append(field).append("\": ").append(num(value, "physics." + field));
    }

    private static void obstacle(StringBuilder sb, Obstacle o, String path) {
        Obstacle body = o instanceof Obstacle.Moving m ? require(m.body(), path + ".body") : o;
        if (body instanceof Obstacle.Bumper b) {
            sb.append("{ \"type\": \"bumper\", \"position\": ");
            vec(sb, require(b.position(), path + ".position"), path + ".position");
            sb.append(", \"radius\": ").append(num(b.radius(), path + ".radius"))
                    .append(", \"height\": ").append(num(b.height(), path + ".height"));
        } else if (body instanceof Obstacle.Gate g) {
            sb.append("{ \"type\": \"gate\", \"from\": ");
            vec(sb, require(g.from(), path + ".from"), path + ".from");
            sb.append(", \"to\": ");
            vec(sb, require(g.to(), path + ".to"), path + ".to");
            sb.append(", \"height\": ").append(num(g.height(), path + ".height"))
                    .append(", \"passTo\": ").append(quote(require(g.passTo(), path + ".passTo").jsonName()));
        } else {
            stillObstacle(sb, body, path);
        }
        sb.append(", \"restitution\": ").append(num(o.restitution(), path + ".restitution"));
        if (o instanceof Obstacle.Moving m) {
            sb.append(", \"motion\": ");
            ElementWriter.motion(sb, require(m.motion(), path + ".motion"), path + ".motion");
        }
        sb.append(" }");
    }

    private static void stillObstacle(StringBuilder sb, Obstacle o, String path) {
        if (o instanceof Obstacle.Wall w) {
            sb.append("{ \"type\": \"wall\", \"from\": ");
            vec(sb, require(w.from(), path + ".from"), path + ".from");
            sb.append(", \"to\": ");
            vec(sb, require(w.to(), path + ".to"), path + ".to");
            sb.append(", \"thickness\": ").append(num(w.thickness(), path + ".thickness"))
                    .append(", \"height\": ").append(num(w.height(), path + ".height"));
        } else if (o instanceof Obstacle.Tree t) {
            sb.append("{ \"type\": \"tree\", \"position\": ");
            vec(sb, require(t.position(), path + ".position"), path + ".position");
            sb.append(", \"radius\": ").append(num(t.radius(), path + ".radius"))
                    .append(", \"height\": ").append(num(t.height(), path + ".height"));
        } else if (o instanceof Obstacle.Box b) {
            sb.append("{ \"type\": \"box\", \"min\": ");
            vec3(sb, require(b.min(), path + ".min"), path + ".min");
            sb.append(", \"max\": ");
            vec3(sb, require(b.max(), path + ".max"), path + ".max");
            sb.append(", \"rotationDeg\": ").append(num(b.rotationDeg(), path + ".rotationDeg"));
        } else {
            Obstacle.Model m = (Obstacle.Model) o;
            sb.append("{ \"type\": \"model\", \"file\": ").append(quote(require(m.file(), path + ".file")))
                    .append(", \"position\": ");
            vec3(sb, require(m.position(), path + ".position"), path + ".position");
            sb.append(", \"rotationDeg\": ").append(num(m.rotationDeg(), path + ".rotationDeg"))
                    .append(", \"scale\": ").append(num(m.scale(), path + ".scale"));
        }
    }

    static void vec3(StringBuilder sb, Vec3 v, String path) {
        sb.append('[').append(num(v.x(), path)).append(", ").append(num(v.y(), path)).append(", ")
                .append(num(v.z(), path)).append(']');
    }

    /** A hole as one JSON object: position, radius, rule and (when set) capture speed. */
    private static void hole(StringBuilder sb, Hole h, String path) {
        sb.append("{ \"position\": ");
        vec(sb, require(h.position(), path + ".position"), path + ".position");
        sb.append(", \"radius\": ").append(num(h.radius(), path + ".radius"))
                .append(", \"rule\": ").append(quote(require(h.rule(), path + ".rule").jsonName()));
        if (h.captureSpeed() != null) {
            sb.append(", \"captureSpeed\": ").append(num(h.captureSpeed(), path + ".captureSpeed"));
        }
        sb.append(" }");
    }

    static void vec(StringBuilder sb, Vec2 v, String path) {
        vec(sb, v.x(), v.y(), path);
    }

    private static void vec(StringBuilder sb, double x, double y, String path) {
        sb.append('[').append(num(x, path)).append(", ").append(num(y, path)).append(']');
    }

    /**
     * A double in a form Jackson reads back to the same bits: Java's round-trip repr, with a
     * trailing ".0" dropped for integers (but -0.0 stays "-0.0": "-0" would read back as +0).
     */
    static String num(double v, String path) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException(path + ": not a finite number: " + v);
        String s = Double.toString(v);
        if (s.endsWith(".0") && !(v == 0 && 1 / v < 0)) s = s.substring(0, s.length() - 2);
        return s;
    }

    static String quote(String s) {
        return '"' + new String(JsonStringEncoder.getInstance().quoteAsString(s)) + '"';
    }

    static <T> T require(T value, String path) {
        if (value == null) throw new IllegalArgumentException(path + ": missing (null)");
        return value;
    }
}
