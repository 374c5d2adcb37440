package minigolf.scenery;

import minigolf.course.Bounds;
import minigolf.theme.Theme;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

/**
 * Where a world's props stand round a course: each kind in its own band of distances from the
 * course's bounds (flowers and lamp posts close by, rocks and trees round about, buttes on the
 * skyline), never on the course, spaced apart, denser near the course; the castle beyond the hole
 * (seen from the tee), the lighthouse to one side on the shore, beach huts in a row facing the
 * sea. Seeded from the bounds, so a course always gets the same scenery. Plain Java.
 */
public final class SceneryPlan {
    /** One placed prop: its kind, foot point, size (metres: height, or width for buttes and castles), heading and seed. */
    public record Placed(Theme.Prop prop, double x, double y, double size, double headingDeg, long seed) {
        /** Buttes are drawn with a longer fade (they stand on the skyline). */
        public boolean skyline() {
            return prop == Theme.Prop.MESA || prop == Theme.Prop.CASTLE || prop == Theme.Prop.LIGHTHOUSE;
        }
    }

    /** Distance band from the bounds (metres), size range and spacing per kind. */
    record Rule(double minDistance, double maxDistance, double minSize, double maxSize, double spacing) {
    }

    static Rule rule(Theme.Prop p) {
        return switch (p) {
            case TREE -> new Rule(3, 60, 2.2, 4.4, 2.5);
            case PINE -> new Rule(4, 55, 3.0, 7.0, 2.5);
            case ROCK -> new Rule(1.2, 30, 0.4, 1.6, 1.6);
            case CACTUS -> new Rule(2.5, 45, 1.4, 3.2, 2.5);
            case FLOWERS -> new Rule(0.6, 5, 1, 1, 0.9);
            case FENCE -> new Rule(2.5, 8, 3, 5, 3.0);
            case LAMP_POST -> new Rule(2.0, 4.0, 1, 1, 4.0);
            case CASTLE -> new Rule(16, 20, 24, 24, 0);
            case MESA -> new Rule(70, 170, 25, 60, 35);
            case LIGHTHOUSE -> new Rule(0, 0, 1, 1, 0);
            case HUT -> new Rule(0, 0, 1, 1, 2.3);
            case SNOWDRIFT -> new Rule(1.5, 25, 1.5, 4.0, 2.5);
            case DUNE -> new Rule(3, 30, 2.0, 4.0, 3.0);
        };
    }

    private SceneryPlan() {
    }

    /**
     * The props of {@code scenery} round {@code b}, {@code share} of each kind's count (1 at high
     * quality, less on software rasterisers; at least one of each kind), for a course played from
     * (sx, sy) towards the hole at (hx, hy).
     */
    public static List<Placed> plan(Theme.Scenery scenery, Bounds b, double sx, double sy, double hx, double hy, double share) {
        Random random = new Random(seedOf(b));
        List<Placed> out = new ArrayList<>();
        double dx = hx - sx, dy = hy - sy, len = Math.hypot(dx, dy);
        double fx = len > 0 ? dx / len : 1, fy = len > 0 ? dy / len : 0;
        double cx = (b.minX() + b.maxX()) / 2, cy = (b.minY() + b.maxY()) / 2;
        for (Theme.PropCount pc : scenery.props()) {
            Theme.Prop p = pc.prop();
            int count = Math.max(1, (int) Math.round(pc.count() * share));
            Rule rule = rule(p);
            double maxDistance = scenery.sea() ? Math.min(rule.maxDistance(), scenery.shoreDistance() - 1) : rule.maxDistance();
            switch (p) {
                case CASTLE -> {
                    // Beyond the hole, seen from the tee, facing back towards the course.
                    double reach = rayToEdge(b, cx, cy, fx, fy) + rule.minDistance() + rule.maxSize() * 0.45;
                    double facing = Math.toDegrees(Math.atan2(-fy, -fx));
                    out.add(new Placed(p, cx + fx * reach, cy + fy * reach, rule.maxSize(), facing < 0 ? facing + 360 : facing, 1));
                }
                case LIGHTHOUSE -> {
                    double side = random.nextBoolean() ? 1 : -1;
                    double ox = -fy * side * 0.8 + fx * 0.6, oy = fx * side * 0.8 + fy * 0.6;
                    double l = Math.hypot(ox, oy);
                    ox /= l;
                    oy /= l;
                    double reach = rayToEdge(b, cx, cy, ox, oy) + Math.max(scenery.shoreDistance(), 6) + 1.5;
                    out.add(new Placed(p, cx + ox * reach, cy + oy * reach, 1, 0, 2));
                }
                case HUT -> {
                    // A row along the far side from the tee's view, near the shore, facing the sea.
                    double side = random.nextBoolean() ? 1 : -1;
                    double nx = -fy * side, ny = fx * side;
                    double reach = rayToEdge(b, cx, cy, nx, ny) + Math.max(3, scenery.shoreDistance() - 4.5);
                    for (int k = 0; k < count; k++) {
                        double along = (k - (count - 1) / 2.0) * rule.spacing();
                        out.add(new Placed(p, cx + nx * reach + fx * along, cy + ny * reach + fy * along, 1,
                                Math.toDegrees(Math.atan2(ny, nx)), k));
                    }
                }
                default -> scatter(p, count, rule, maxDistance, b, random, out);
            }
        }
        return List.copyOf(out);
    }

    /** Rejection sampling in the band round the bounds, kept apart from everything placed so far. */
    private static void scatter(Theme.Prop p, int count, Rule rule, double maxDistance, Bounds b, Random random, List<Placed> out) {
        int placed = 0;
        for (int tries = 0; placed < count && tries < 300 * count; tries++) {
            double x = b.minX() - maxDistance + random.nextDouble() * (b.width() + 2 * maxDistance);
            double y = b.minY() - maxDistance + random.nextDouble() * (b.depth() + 2 * maxDistance);
            double d = distance(b, x, y);
            if (d < rule.minDistance() || d > maxDistance) continue;
            if (random.nextDouble() > Math.pow(Math.max(rule.minDistance(), 0.5) / d, 0.6)) continue;
            double size = rule.minSize() + (rule.maxSize() - rule.minSize()) * random.nextDouble();
            if (crowded(out, x, y, Math.max(rule.spacing(), p == Theme.Prop.MESA ? size : 0))) continue;
            double heading = p == Theme.Prop.FENCE ? alongNearestSide(b, x, y) : random.nextDouble() * 360;
            out.add(new Placed(p, x, y, size, heading, random.nextLong()));
            placed++;
        }
    }

    private static boolean crowded(List<Placed> placed, double x, double y, double spacing) {
        for (Placed q : placed) {
            double need = Math.max(spacing, rule(q.prop()).spacing());
            if (q.prop() == Theme.Prop.CASTLE) need = q.size() * 0.8;
            if (Math.hypot(q.x() - x, q.y() - y) < need) return true;
        }
        return false;
    }

    /** The heading (degrees) of the bounds' side nearest to (x, y): fences run along the course. */
    static double alongNearestSide(Bounds b, double x, double y) {
        double dx = Math.max(b.minX() - x, x - b.maxX()), dy = Math.max(b.minY() - y, y - b.maxY());
        return dx > dy ? 90 : 0;
    }

    /** How far from (x, y) inside the bounds the ray along the unit (ux, uy) leaves them. */
    static double rayToEdge(Bounds b, double x, double y, double ux, double uy) {
        double t = Double.POSITIVE_INFINITY;
        if (ux > 1e-9) t = Math.min(t, (b.maxX() - x) / ux);
        if (ux < -1e-9) t = Math.min(t, (b.minX() - x) / ux);
        if (uy > 1e-9) t = Math.min(t, (b.maxY() - y) / uy);
        if (uy < -1e-9) t = Math.min(t, (b.minY() - y) / uy);
        return Double.isInfinite(t) ? 0 : Math.max(0, t);
    }

    /** Distance from (x, y) to the bounds' rectangle (0 inside). */
    public static double distance(Bounds b, double x, double y) {
        double dx = Math.max(Math.max(b.minX() - x, x - b.maxX()), 0);
        double dy = Math.max(Math.max(b.minY() - y, y - b.maxY()), 0);
        return Math.hypot(dx, dy);
    }

    /** The seed a course's bounds give (as the trees' in minigolf.render.TreePlacement, another stream). */
    public static long seedOf(Bounds b) {
        long h = 0x9E3779B97F4A7C15L;
        for (double d : new double[]{b.minX(), b.minY(), b.maxX(), b.maxY()}) h = 31 * h + Double.hashCode(d);
        return h;
    }
}
