package minigolf.bot.map;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;
import minigolf.collision.ObstacleGeometry;
import minigolf.course.Obstacle;
import minigolf.course.Segments;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/**
 * Where a resting or rolling ball cannot be because an obstacle is there: the obstacles' shapes seen
 * from above, inflated by the ball's radius. Walls and boxes are exact rectangles (boxes only where
 * their height range meets a rolling ball's, so a ball may roll under a raised box); trees are
 * circles (reported as {@link #TREE} for A*'s diagonal rule); models are their triangles
 * ({@link ObstacleGeometry}, as the physics places them) projected onto the ground, those that
 * reach from the ground up to the ball's top; the breakable bricks standing in the world's state
 * as boxes. Built once per world and cached.
 */
public final class ObstacleFootprint {
    /** {@link #BRICK}: only a standing breakable brick is in the way (the ball can break it). */
    public static final byte FREE = 0, SOLID = 1, TREE = 2, BRICK = 3;

    private static final Map<World, ObstacleFootprint> CACHE = new WeakHashMap<>();
    private static final double BUCKET = 0.5;

    private final Terrain terrain;
    private final double radius;
    /** Per shape: kind, then geometry (see the shape kinds below). */
    private final List<double[]> shapes = new ArrayList<>();
    private final double minX, minY;
    private final int cols, rows;
    private final int[][] buckets;
    /** Shapes from this index on are the standing bricks. */
    private final int firstBrick;

    private static final int RECT = 0, CIRCLE = 1, TRIANGLE = 2;

    private ObstacleFootprint(World world) {
        this.terrain = world.terrain();
        this.radius = world.physics().ballRadius();
        for (Obstacle o : world.course().obstacles()) add(o);
        firstBrick = shapes.size();
        // The bricks standing in this world's state are boxes; broken ones leave the way open.
        for (int i = 0; i < world.state().bricks(); i++) {
            if (world.state().standing(i)) add(world.course().bricks().get(i).box());
        }
        minX = world.bounds().minX() - 1;
        minY = world.bounds().minY() - 1;
        cols = Math.max(1, (int) Math.ceil((world.bounds().width() + 2) / BUCKET));
        rows = Math.max(1, (int) Math.ceil((world.bounds().depth() + 2) / BUCKET));
        List<List<Integer>> lists = new ArrayList<>();
        for (int i = 0; i < cols * rows; i++) lists.add(new ArrayList<>());
        // Listed in every bucket within the largest inflation a query uses (ball radius + a cell diagonal).
        double pad = radius + 1.0;
        for (int s = 0; s < shapes.size(); s++) {
            double[] b = bbox(shapes.get(s));
            for (int r = bucketRow(b[1] - pad); r <= bucketRow(b[3] + pad); r++) {
                for (int c = bucketCol(b[0] - pad); c <= bucketCol(b[2] + pad); c++) lists.get(r * cols + c).add(s);
            }
        }
        buckets = new int[cols * rows][];
        for (int i = 0; i < buckets.length; i++) buckets[i] = lists.get(i).stream().mapToInt(Integer::intValue).toArray();
    }

    /** The footprint of a world's obstacles (cached per world; worlds are immutable). */
    public static ObstacleFootprint of(World world) {
        synchronized (CACHE) {
            return CACHE.computeIfAbsent(world, ObstacleFootprint::new);
        }
    }

    private void add(Obstacle o) {
        if (o instanceof Obstacle.Wall w) {
            double ax = w.from().x(), ay = w.from().y(), bx = w.to().x(), by = w.to().y();
            double length = Math.hypot(bx - ax, by - ay);
            double ux = length > 0 ? (bx - ax) / length : 1, uy = length > 0 ? (by - ay) / length : 0;
            double half = w.thickness() / 2;
            // Square ends reach half the thickness beyond the end points (as ObstacleGeometry builds them).
            shapes.add(new double[] {RECT, (ax + bx) / 2, (ay + by) / 2, ux, uy, length / 2 + half, half,
                    Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY});
        } else if (o instanceof Obstacle.Tree t) {
            shapes.add(new double[] {CIRCLE, t.position().x(), t.position().y(), t.radius()});
        } else if (o instanceof Obstacle.Bumper b) {
            shapes.add(new double[] {CIRCLE, b.position().x(), b.position().y(), b.radius()});
        } else if (o instanceof Obstacle.Box b) {
            double a = Math.toRadians(b.rotationDeg());
            shapes.add(new double[] {RECT, (b.min().x() + b.max().x()) / 2, (b.min().y() + b.max().y()) / 2,
                    Math.cos(a), Math.sin(a), (b.max().x() - b.min().x()) / 2, (b.max().y() - b.min().y()) / 2,
                    b.min().z(), b.max().z()});
        } else if (o instanceof Obstacle.Model m) {
            double[] t = ObstacleGeometry.triangles(m, terrain::height);
            for (int i = 0; i + 9 <= t.length; i += 9) {
                double zMin = Math.min(t[i + 2], Math.min(t[i + 5], t[i + 8]));
                double zMax = Math.max(t[i + 2], Math.max(t[i + 5], t[i + 8]));
                shapes.add(new double[] {TRIANGLE, t[i], t[i + 1], t[i + 3], t[i + 4], t[i + 6], t[i + 7], zMin, zMax});
            }
        }
    }

    public boolean isEmpty() {
        return shapes.isEmpty();
    }

    /**
     * What keeps a ball's centre from (x, y): {@link #FREE}, {@link #SOLID} or {@link #TREE}, with
     * every shape inflated by the ball's radius plus {@code extra} (a grid passes half its cell
     * diagonal, so a thin fence between two cell centres still blocks).
     */
    public byte kind(double x, double y, double extra) {
        if (shapes.isEmpty()) return FREE;
        int c = bucketCol(x), r = bucketRow(y);
        int[] list = buckets[r * cols + c];
        if (list.length == 0) return FREE;
        double reach = radius + extra;
        double ground = terrain.height(x, y);
        byte found = FREE;
        boolean brick = false;
        for (int s : list) {
            double[] p = shapes.get(s);
            double d;
            switch ((int) p[0]) {
                case RECT -> {
                    // A raised box the ball rolls under, or one buried below the ground, does not block.
                    if (p[7] > ground + 2 * radius || p[8] < ground) continue;
                    double dx = x - p[1], dy = y - p[2];
                    double along = Math.abs(dx * p[3] + dy * p[4]) - p[5];
                    double across = Math.abs(-dx * p[4] + dy * p[3]) - p[6];
                    d = Math.hypot(Math.max(along, 0), Math.max(across, 0));
                }
                case CIRCLE -> d = Math.hypot(x - p[1], y - p[2]) - p[3];
                default -> {
                    if (p[7] > ground + 2 * radius || p[8] < ground) continue;
                    d = triangleDistance(x, y, p);
                }
            }
            if (d <= reach) {
                if (s >= firstBrick) {
                    brick = true;
                    continue;
                }
                if ((int) p[0] != CIRCLE) return SOLID;
                found = TREE;
            }
        }
        return found == FREE && brick ? BRICK : found;
    }

    /** Distance in the plane from (x, y) to the triangle (0 inside). */
    private static double triangleDistance(double x, double y, double[] p) {
        double ax = p[1], ay = p[2], bx = p[3], by = p[4], cx = p[5], cy = p[6];
        double d1 = Segments.side(ax, ay, bx, by, x, y), d2 = Segments.side(bx, by, cx, cy, x, y);
        double d3 = Segments.side(cx, cy, ax, ay, x, y);
        boolean negative = d1 < 0 || d2 < 0 || d3 < 0, positive = d1 > 0 || d2 > 0 || d3 > 0;
        if (!(negative && positive)) return 0;
        return Math.min(Segments.distance(x, y, ax, ay, bx, by),
                Math.min(Segments.distance(x, y, bx, by, cx, cy), Segments.distance(x, y, cx, cy, ax, ay)));
    }

    private static double[] bbox(double[] p) {
        return switch ((int) p[0]) {
            case RECT -> {
                double ex = Math.abs(p[3]) * p[5] + Math.abs(p[4]) * p[6], ey = Math.abs(p[4]) * p[5] + Math.abs(p[3]) * p[6];
                yield new double[] {p[1] - ex, p[2] - ey, p[1] + ex, p[2] + ey};
            }
            case CIRCLE -> new double[] {p[1] - p[3], p[2] - p[3], p[1] + p[3], p[2] + p[3]};
            default -> new double[] {Math.min(p[1], Math.min(p[3], p[5])), Math.min(p[2], Math.min(p[4], p[6])),
                    Math.max(p[1], Math.max(p[3], p[5])), Math.max(p[2], Math.max(p[4], p[6]))};
        };
    }

    private int bucketCol(double x) {
        return Math.max(0, Math.min(cols - 1, (int) Math.floor((x - minX) / BUCKET)));
    }

    private int bucketRow(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / BUCKET)));
    }
}
