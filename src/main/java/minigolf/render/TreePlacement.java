package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * Where the decorative trees round a course stand ({@link SurroundingsPass}): scattered outside the
 * course's bounds, from a few metres to about 60 m away, denser near the course. The same bounds
 * always give the same trees (the seed comes from them), so a course looks the same every time.
 * They are only drawn: physics and the camera's clearance never see them.
 */
public final class TreePlacement {
    /** No crown reaches nearer the bounds than this (metres). */
    public static final double MARGIN = 1.5;
    /** Nor does any trunk stand nearer than this. */
    public static final double MIN_DISTANCE = 3.0;
    /** Nor further than this. */
    public static final double MAX_DISTANCE = 60.0;
    /** Trunks keep at least this far apart, so crowns do not merge into one blob. */
    static final double SPACING = 2.5;
    static final double MIN_HEIGHT = 2.2, MAX_HEIGHT = 4.4;

    private TreePlacement() {
    }

    /** The seed a course's bounds give. */
    public static long seedOf(Bounds b) {
        long h = 1125899906842597L;
        for (double d : new double[]{b.minX(), b.minY(), b.maxX(), b.maxY()}) h = 31 * h + Double.hashCode(d);
        return h;
    }

    /** {@code count} trees round {@code b} (fewer if they cannot keep their spacing), seeded from the bounds. */
    public static List<Obstacle.Tree> around(Bounds b, int count) {
        return around(b, count, seedOf(b));
    }

    /** As above with a chosen seed. */
    public static List<Obstacle.Tree> around(Bounds b, int count, long seed) {
        Random random = new Random(seed);
        List<Obstacle.Tree> trees = new ArrayList<>(count);
        double reach = MAX_DISTANCE;
        // Rejection sampling in the square round the bounds; a bounded number of tries keeps it finite.
        for (int tries = 0; trees.size() < count && tries < 200 * Math.max(1, count); tries++) {
            double x = b.minX() - reach + random.nextDouble() * (b.width() + 2 * reach);
            double y = b.minY() - reach + random.nextDouble() * (b.depth() + 2 * reach);
            double height = MIN_HEIGHT + (MAX_HEIGHT - MIN_HEIGHT) * random.nextDouble();
            double radius = height * (0.035 + 0.02 * random.nextDouble());
            double d = distance(b, x, y);
            if (d < Math.max(MIN_DISTANCE, MARGIN + crownSize(height, radius)) || d > MAX_DISTANCE) continue;
            // Denser near the course: the acceptance falls with distance (the ring's area grows with it).
            if (random.nextDouble() > Math.pow(MIN_DISTANCE / d, 0.7)) continue;
            if (crowded(trees, x, y)) continue;
            trees.add(new Obstacle.Tree(new Vec2(x, y), radius, height, 0));
        }
        return List.copyOf(trees);
    }

    /** The crown's size as ObstacleMeshes draws it (the crown model is about this wide either side of the trunk). */
    static double crownSize(double height, double radius) {
        return ObstacleMeshes.CrownStyle.SURROUNDINGS.size(height, radius);
    }

    /** Distance from (x, y) to the bounds' rectangle (0 inside). */
    public static double distance(Bounds b, double x, double y) {
        double dx = Math.max(Math.max(b.minX() - x, x - b.maxX()), 0);
        double dy = Math.max(Math.max(b.minY() - y, y - b.maxY()), 0);
        return Math.hypot(dx, dy);
    }

    private static boolean crowded(List<Obstacle.Tree> trees, double x, double y) {
        for (Obstacle.Tree t : trees) {
            if (Math.hypot(t.position().x() - x, t.position().y() - y) < SPACING) return true;
        }
        return false;
    }
}
