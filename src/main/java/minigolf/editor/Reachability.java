package minigolf.editor;

import java.util.Arrays;
import java.util.PriorityQueue;
import minigolf.collision.CollisionScene;
import minigolf.collision.Hit;
import minigolf.physics.World;

/**
 * Whether a ball could travel from the start to the hole: A* over the course grid's cells
 * (8 neighbours, straight-line distance as the heuristic). A cell can be crossed when it is not
 * deleted, inside the bounds and dry at its centre, and no obstacle covers its centre; a move
 * between two cells is blocked when the ball's sweep from centre to centre hits an obstacle (so a
 * thin fence between two cells blocks them). Slopes and friction are ignored: this finds courses
 * that can never be holed, not how hard a course is.
 */
public final class Reachability {
    private Reachability() {
    }

    /** The path's cells as {i, j} pairs from the start's cell to the hole's, or null if there is none. */
    public static int[][] path(EditableCourse c, World world) {
        int cols = c.columns - 1, rows = c.rows - 1;
        double sx = world.course().start().x(), sy = world.course().start().y();
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        int si = c.cellColumn(sx), sj = c.cellRow(sy), gi = c.cellColumn(hx), gj = c.cellRow(hy);
        if (si < 0 || sj < 0 || gi < 0 || gj < 0) return null;
        byte[] open = new byte[cols * rows]; // 0 unknown, 1 passable, 2 blocked
        CollisionScene scene = world.obstacles();
        Hit hit = new Hit();
        double[] scratch = new double[3];
        double r = world.physics().ballRadius();
        double[] g = new double[cols * rows];
        Arrays.fill(g, Double.POSITIVE_INFINITY);
        int[] from = new int[cols * rows];
        boolean[] closed = new boolean[cols * rows];
        int start = sj * cols + si, goal = gj * cols + gi;
        PriorityQueue<double[]> queue = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        g[start] = 0;
        from[start] = -1;
        queue.add(new double[]{0, start});
        while (!queue.isEmpty()) {
            int cur = (int) queue.poll()[1];
            if (closed[cur]) continue;
            if (cur == goal) return trace(from, cur, cols);
            closed[cur] = true;
            int ci = cur % cols, cj = cur / cols;
            double cx = centerX(c, ci), cy = centerY(c, cj);
            for (int dj = -1; dj <= 1; dj++) {
                for (int di = -1; di <= 1; di++) {
                    if (di == 0 && dj == 0) continue;
                    int ni = ci + di, nj = cj + dj;
                    if (ni < 0 || nj < 0 || ni >= cols || nj >= rows) continue;
                    int n = nj * cols + ni;
                    if (closed[n]) continue;
                    if (open[n] == 0) open[n] = passable(c, world, scene, ni, nj, r) ? (byte) 1 : (byte) 2;
                    if (open[n] == 2 && n != goal) continue;
                    // Diagonal moves may not cut the corner of a blocked or deleted cell.
                    if (di != 0 && dj != 0) {
                        int a = cj * cols + ni, b = nj * cols + ci;
                        if (open[a] == 0) open[a] = passable(c, world, scene, ni, cj, r) ? (byte) 1 : (byte) 2;
                        if (open[b] == 0) open[b] = passable(c, world, scene, ci, nj, r) ? (byte) 1 : (byte) 2;
                        if (open[a] == 2 || open[b] == 2) continue;
                    }
                    double nx = centerX(c, ni), ny = centerY(c, nj);
                    if (scene != null && scene.anyNear(Math.min(cx, nx) - r, Math.min(cy, ny) - r,
                            Math.max(cx, nx) + r, Math.max(cy, ny) + r)) {
                        double z0 = world.terrain().height(cx, cy) + r, z1 = world.terrain().height(nx, ny) + r;
                        if (scene.sweep(cx, cy, z0, nx, ny, z1, hit, scratch)) continue;
                    }
                    double cost = g[cur] + Math.hypot(di, dj);
                    if (cost < g[n]) {
                        g[n] = cost;
                        from[n] = cur;
                        queue.add(new double[]{cost + Math.hypot(ni - gi, nj - gj), n});
                    }
                }
            }
        }
        return null;
    }

    private static boolean passable(EditableCourse c, World world, CollisionScene scene, int i, int j, double r) {
        if (c.isDeleted(i, j)) return false;
        double x = centerX(c, i), y = centerY(c, j);
        if (!world.bounds().contains(x, y)) return false;
        double h = world.terrain().height(x, y);
        if (h < 0) return false;
        return scene == null || !scene.anyNear(x - r, y - r, x + r, y + r) || scene.clearance(x, y, h + r) >= r;
    }

    static double centerX(EditableCourse c, int i) {
        return c.originX + (i + 0.5) * c.spacing;
    }

    static double centerY(EditableCourse c, int j) {
        return c.originY + (j + 0.5) * c.spacing;
    }

    private static int[][] trace(int[] from, int end, int cols) {
        int n = 0;
        for (int k = end; k != -1; k = from[k]) n++;
        int[][] path = new int[n][];
        for (int k = end, m = n - 1; k != -1; k = from[k], m--) path[m] = new int[]{k % cols, k / cols};
        return path;
    }
}
