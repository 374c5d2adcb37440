package minigolf.editor;

import minigolf.bot.CancellationToken;
import minigolf.bot.map.GridPathSearch;
import minigolf.collision.CollisionScene;
import minigolf.collision.Hit;
import minigolf.physics.World;

/**
 * Whether a ball could travel from the start to the hole: A* over the course grid's cells
 * (8 neighbours, straight-line distance as the heuristic). A cell can be crossed when it is not
 * deleted, inside the bounds and dry at its centre, and no obstacle covers its centre; a move
 * between two cells is blocked when the ball's sweep from centre to centre hits an obstacle (so a
 * thin fence between two cells blocks them). Slopes and friction are ignored: this finds courses
 * that can never be holed, not how hard a course is. The search is the bots' {@link GridPathSearch}.
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
        int goal = gj * cols + gi;
        GridPathSearch.Graph graph = new GridPathSearch.Graph() {
            /** Whether cell (i, j) can be crossed, worked out on first use. */
            boolean blocked(int i, int j) {
                int k = j * cols + i;
                if (open[k] == 0) open[k] = passable(c, world, scene, i, j, r) ? (byte) 1 : (byte) 2;
                return open[k] == 2;
            }

            @Override
            public double stepCost(int ci, int cj, int di, int dj) {
                int ni = ci + di, nj = cj + dj;
                if (blocked(ni, nj) && nj * cols + ni != goal) return Double.POSITIVE_INFINITY;
                // Diagonal moves may not cut the corner of a blocked or deleted cell.
                if (di != 0 && dj != 0 && (blocked(ni, cj) || blocked(ci, nj))) return Double.POSITIVE_INFINITY;
                double cx = centerX(c, ci), cy = centerY(c, cj), nx = centerX(c, ni), ny = centerY(c, nj);
                if (scene != null && scene.anyNear(Math.min(cx, nx) - r, Math.min(cy, ny) - r,
                        Math.max(cx, nx) + r, Math.max(cy, ny) + r)) {
                    double z0 = world.terrain().height(cx, cy) + r, z1 = world.terrain().height(nx, ny) + r;
                    if (scene.sweep(cx, cy, z0, nx, ny, z1, hit, scratch)) return Double.POSITIVE_INFINITY;
                }
                return Math.hypot(di, dj);
            }

            @Override
            public double heuristic(int i, int j) {
                return Math.hypot(i - gi, j - gj);
            }
        };
        int[] cells = GridPathSearch.path(cols, rows, sj * cols + si, goal, graph, true, CancellationToken.none());
        if (cells == null) return null;
        int[][] path = new int[cells.length][];
        for (int m = 0; m < cells.length; m++) path[m] = new int[] {cells[m] % cols, cells[m] / cols};
        return path;
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
}
