package minigolf.course;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.List;

/** Checks of a course that need more than its own fields: where the start and the hole lie on the terrain. */
public final class CourseValidator {
    private CourseValidator() {
    }

    /**
     * Checks that the start and the hole's centre are inside the bounds and on dry land
     * (h &ge; 0 according to {@code probe}). Errors read e.g.
     * {@code courses/x.json: start: (-3, 0) is in water (h = -0.12)}.
     */
    public static void checkPlacement(Course course, HeightProbe probe, String sourceName) throws CourseException {
        checkInBounds(course, sourceName);
        checkDry(course.start(), "start", probe, sourceName);
        checkDry(course.hole().position(), "hole.position", probe, sourceName);
        for (int i = 0; i < course.extraHoles().size(); i++) {
            checkDry(course.extraHoles().get(i).position(), extraHolePath(i), probe, sourceName);
        }
        for (int i = 0; i < course.teleports().size(); i++) {
            List<Teleport.Exit> exits = course.teleports().get(i).exits();
            for (int k = 0; k < exits.size(); k++) {
                checkDry(exits.get(k).position(), "teleports[" + i + "].exits[" + k + "].position", probe, sourceName);
            }
        }
        checkHeights(course, probe, sourceName);
    }

    /** Samples per axis of the terrain height check. */
    static final int HEIGHT_SAMPLES = 33;

    /**
     * The terrain's height over the bounds, sampled on a 33 x 33 grid, must be finite and within
     * {@link Limits#HEIGHT}: a formula such as exp(exp(exp(exp(x)))) overflows or gives a wall a ball
     * bounces on forever.
     */
    static void checkHeights(Course course, HeightProbe probe, String sourceName) throws CourseException {
        Bounds b = course.bounds();
        String path = course.terrain() instanceof TerrainSpec.HeightExpression ? "terrain.height" : "terrain.grid.heights";
        for (int j = 0; j < HEIGHT_SAMPLES; j++) {
            for (int i = 0; i < HEIGHT_SAMPLES; i++) {
                double x = b.minX() + (b.maxX() - b.minX()) * i / (HEIGHT_SAMPLES - 1);
                double y = b.minY() + (b.maxY() - b.minY()) * j / (HEIGHT_SAMPLES - 1);
                double h;
                try {
                    h = probe.height(x, y);
                } catch (RuntimeException e) {
                    throw new CourseException(sourceName, path, "cannot evaluate the terrain height at "
                            + point(new Vec2(x, y)) + ": " + e.getMessage(), e);
                }
                if (!(Math.abs(h) <= Limits.HEIGHT)) {
                    throw new CourseException(sourceName, path, "the height at " + point(new Vec2(x, y)) + " is "
                            + approx(h) + ": heights must be finite and within +-" + number(Limits.HEIGHT) + " m");
                }
            }
        }
    }

    /** The part of {@link #checkPlacement} that needs no terrain: start and hole centre inside the bounds. */
    static void checkInBounds(Course course, String sourceName) throws CourseException {
        checkInBounds(course.start(), "start", course.bounds(), sourceName);
        checkInBounds(course.hole().position(), "hole.position", course.bounds(), sourceName);
        if (course.terrain() instanceof TerrainSpec.HeightGrid g && g.deleted() != null) {
            checkNotDeleted(course.start(), "start", g, sourceName);
            checkNotDeleted(course.hole().position(), "hole.position", g, sourceName);
        }
        for (int i = 0; i < course.extraHoles().size(); i++) {
            Vec2 p = course.extraHoles().get(i).position();
            checkInBounds(p, extraHolePath(i), course.bounds(), sourceName);
            if (course.terrain() instanceof TerrainSpec.HeightGrid g && g.deleted() != null) {
                checkNotDeleted(p, extraHolePath(i), g, sourceName);
            }
        }
        checkTeleports(course, sourceName);
        checkNoHazard(course.start(), "start", course, sourceName);
        checkBricks(course, sourceName);
    }

    /** No brick stands on the start or a hole (the ball would start inside it; a hole could never be reached). */
    private static void checkBricks(Course course, String sourceName) throws CourseException {
        for (int i = 0; i < course.bricks().size(); i++) {
            Brick b = course.bricks().get(i);
            for (int k = 0; k <= course.holes().size(); k++) {
                Vec2 p = k == 0 ? course.start() : course.holes().get(k - 1).position();
                if (p.x() > b.min().x() && p.x() < b.max().x() && p.y() > b.min().y() && p.y() < b.max().y()) {
                    throw new CourseException(sourceName, "bricks[" + i + "]", "stands on the "
                            + (k == 0 ? "start" : k == 1 ? "hole" : "hole extraHoles[" + (k - 2) + "]") + " at " + point(p));
                }
            }
        }
    }

    /**
     * Teleport exits lie in the play area, and no exit, the start or the hole lies in a teleport's
     * entry: a ball would be sent on at once, round and round.
     */
    private static void checkTeleports(Course course, String sourceName) throws CourseException {
        List<Teleport> teleports = course.teleports();
        for (int i = 0; i < teleports.size(); i++) {
            List<Teleport.Exit> exits = teleports.get(i).exits();
            for (int k = 0; k < exits.size(); k++) {
                String path = "teleports[" + i + "].exits[" + k + "].position";
                Vec2 p = exits.get(k).position();
                checkInBounds(p, path, course.bounds(), sourceName);
                if (course.terrain() instanceof TerrainSpec.HeightGrid g && g.deleted() != null) {
                    checkNotDeleted(p, path, g, sourceName);
                }
                checkOutsideEntries(p, path, teleports, sourceName);
            }
        }
        checkOutsideEntries(course.start(), "start", teleports, sourceName);
        checkOutsideEntries(course.hole().position(), "hole.position", teleports, sourceName);
        for (int i = 0; i < course.extraHoles().size(); i++) {
            checkOutsideEntries(course.extraHoles().get(i).position(), extraHolePath(i), teleports, sourceName);
        }
    }

    private static String extraHolePath(int i) {
        return "extraHoles[" + i + "].position";
    }

    private static void checkOutsideEntries(Vec2 p, String path, List<Teleport> teleports, String sourceName)
            throws CourseException {
        for (int j = 0; j < teleports.size(); j++) {
            if (teleports.get(j).entry().contains(p.x(), p.y())) {
                throw new CourseException(sourceName, path, point(p) + " is inside the entry of teleports[" + j
                        + "] (the ball would be sent on at once)");
            }
        }
    }

    /**
     * The start may not lie in a hazard zone the ball ends in on entering: the first stroke would
     * end before it began (one it ends in only at rest, as shallow water, is allowed).
     */
    private static void checkNoHazard(Vec2 p, String path, Course course, String sourceName) throws CourseException {
        Zone decisive = null;
        for (Zone z : course.zones()) {
            if (z.shape().contains(p.x(), p.y())) decisive = z; // later zones win
        }
        if (decisive != null && decisive.hazard() != null && decisive.hazard().when() == Zone.Hazard.When.ENTER) {
            throw new CourseException(sourceName, path, point(p) + " is in a " + decisive.hazard().kind().jsonName()
                    + " zone");
        }
    }

    private static void checkNotDeleted(Vec2 p, String path, TerrainSpec.HeightGrid g, String sourceName)
            throws CourseException {
        if (g.isDeletedAt(p.x(), p.y())) {
            throw new CourseException(sourceName, path, point(p) + " is on a deleted terrain cell (out of bounds)");
        }
    }

    private static void checkInBounds(Vec2 p, String path, Bounds bounds, String sourceName) throws CourseException {
        if (!bounds.contains(p.x(), p.y())) {
            throw new CourseException(sourceName, path, point(p) + " is outside the bounds");
        }
    }

    private static void checkDry(Vec2 p, String path, HeightProbe probe, String sourceName) throws CourseException {
        double h;
        try {
            h = probe.height(p.x(), p.y());
        } catch (RuntimeException e) {
            throw new CourseException(sourceName, path,
                    "cannot evaluate the terrain height at " + point(p) + ": " + e.getMessage(), e);
        }
        if (Double.isNaN(h)) {
            throw new CourseException(sourceName, path, "the terrain height at " + point(p) + " is not a number");
        }
        if (h < 0) {
            throw new CourseException(sourceName, path, point(p) + " is in water (h = " + approx(h) + ")");
        }
    }

    static String point(Vec2 p) {
        return "(" + number(p.x()) + ", " + number(p.y()) + ")";
    }

    /** A number as it was written: 0.15, -3, 1.0E-5 (integers without ".0"). */
    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15 && !(v == 0 && 1 / v < 0)) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    /** A computed value to 4 significant digits: -0.1234. */
    static String approx(double v) {
        if (!Double.isFinite(v) || v == 0) return number(v);
        double a = Math.abs(v);
        if (a < 1e-4 || a >= 1e9) return String.format(java.util.Locale.ROOT, "%.3e", v);
        return new BigDecimal(v).round(new MathContext(4)).stripTrailingZeros().toPlainString();
    }
}
