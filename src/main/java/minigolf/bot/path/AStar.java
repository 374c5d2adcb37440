package minigolf.bot.path;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.PriorityQueue;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseGrid;

/**
 * A* on a grid of cells, as in the seed: Manhattan heuristic, 8 neighbours. A diagonal step may
 * not pass a wall (so never between two walls either); it may pass trees, even between two.
 * Water and the course's edge count as walls.
 */
public final class AStar {
    public static final byte FREE = 0, WALL = 1, TREE = 2;

    private final int cols, rows;
    private final byte[] kinds;

    public AStar(int cols, int rows, byte[] kinds) {
        if (kinds.length != cols * rows) throw new IllegalArgumentException("kinds must have cols*rows cells");
        this.cols = cols;
        this.rows = rows;
        this.kinds = kinds.clone();
    }

    /** The grid of a course: cells blocked by trees only are trees, other blocked cells (water, edge, walls, boxes, models) walls. */
    public static AStar of(CourseGrid grid) {
        byte[] kinds = new byte[grid.cols() * grid.rows()];
        for (int i = 0; i < kinds.length; i++) kinds[i] = grid.tree(i) ? TREE : grid.blocked(i) ? WALL : FREE;
        return new AStar(grid.cols(), grid.rows(), kinds);
    }

    public byte kind(int c, int r) {
        return c < 0 || r < 0 || c >= cols || r >= rows ? WALL : kinds[r * cols + c];
    }

    boolean diagonalAllowed(int c, int r, int dc, int dr) {
        return kind(c + dc, r) != WALL && kind(c, r + dr) != WALL;
    }

    /** Cells (c, r) from start to goal inclusive, or an empty list when the goal cannot be reached. */
    public List<int[]> path(int startC, int startR, int goalC, int goalR, CancellationToken token) {
        int n = cols * rows;
        double[] g = new double[n];
        Arrays.fill(g, Double.POSITIVE_INFINITY);
        int[] parent = new int[n];
        Arrays.fill(parent, -1);
        boolean[] closed = new boolean[n];
        int start = startR * cols + startC, goal = goalR * cols + goalC;
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        g[start] = 0;
        open.add(new double[] {Math.abs(goalC - startC) + Math.abs(goalR - startR), start});
        int expanded = 0;
        while (!open.isEmpty()) {
            int i = (int) open.poll()[1];
            if (closed[i]) continue;
            closed[i] = true;
            if ((++expanded & 1023) == 0) token.throwIfCancelled();
            if (i == goal) break;
            int c = i % cols, r = i / cols;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if ((dc == 0 && dr == 0) || kind(c + dc, r + dr) != FREE) continue;
                    boolean diagonal = dc != 0 && dr != 0;
                    if (diagonal && !diagonalAllowed(c, r, dc, dr)) continue;
                    int j = (r + dr) * cols + c + dc;
                    double cost = g[i] + (diagonal ? Math.sqrt(2) : 1);
                    if (cost < g[j]) {
                        g[j] = cost;
                        parent[j] = i;
                        open.add(new double[] {cost + Math.abs(goalC - c - dc) + Math.abs(goalR - r - dr), j});
                    }
                }
            }
        }
        List<int[]> cells = new ArrayList<>();
        if (!closed[goal]) return cells;
        for (int i = goal; i != -1; i = parent[i]) cells.add(new int[] {i % cols, i / cols});
        Collections.reverse(cells);
        return cells;
    }
}
