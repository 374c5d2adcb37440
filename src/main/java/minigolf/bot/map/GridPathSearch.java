package minigolf.bot.map;

import java.util.Arrays;
import java.util.PriorityQueue;
import minigolf.bot.CancellationToken;

/**
 * A* over a grid of cells, 8 neighbours: the one path search of the bots ({@code AStar}) and the
 * editor's reachability check ({@code minigolf.editor.Reachability}). What may be crossed, what a
 * step costs and the heuristic come from the caller's {@link Graph}; the search itself (the open
 * list, ties, when the goal counts as reached) is the same for both.
 */
public final class GridPathSearch {
    /** The grid as the search sees it. */
    public interface Graph {
        /**
         * The cost of the step from cell (c, r) by (dc, dr) (each -1, 0 or 1, not both 0; the target
         * is inside the grid), or infinity when the step is not allowed.
         */
        double stepCost(int c, int r, int dc, int dr);

        /** The estimate of the cost from (c, r) to the goal. */
        double heuristic(int c, int r);
    }

    private GridPathSearch() {
    }

    /**
     * The cells (indices r * cols + c) from start to goal inclusive, or null when the goal cannot
     * be reached. A cell is expanded once (the first time it leaves the open list); with
     * {@code skipClosed} steps into expanded cells are not even priced. Checks the token every
     * 1024 expanded cells.
     */
    public static int[] path(int cols, int rows, int start, int goal, Graph graph, boolean skipClosed,
                             CancellationToken token) {
        int n = cols * rows;
        double[] g = new double[n];
        Arrays.fill(g, Double.POSITIVE_INFINITY);
        int[] parent = new int[n];
        Arrays.fill(parent, -1);
        boolean[] closed = new boolean[n];
        PriorityQueue<double[]> open = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        g[start] = 0;
        open.add(new double[] {graph.heuristic(start % cols, start / cols), start});
        int expanded = 0;
        while (!open.isEmpty()) {
            int i = (int) open.poll()[1];
            if (closed[i]) continue;
            if (i == goal) return trace(parent, goal);
            closed[i] = true;
            if ((++expanded & 1023) == 0) token.throwIfCancelled();
            int c = i % cols, r = i / cols;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if (dc == 0 && dr == 0) continue;
                    int nc = c + dc, nr = r + dr;
                    if (nc < 0 || nr < 0 || nc >= cols || nr >= rows) continue;
                    int j = nr * cols + nc;
                    if (skipClosed && closed[j]) continue;
                    double step = graph.stepCost(c, r, dc, dr);
                    if (!(step < Double.POSITIVE_INFINITY)) continue;
                    double cost = g[i] + step;
                    if (cost < g[j]) {
                        g[j] = cost;
                        parent[j] = i;
                        open.add(new double[] {cost + graph.heuristic(nc, nr), j});
                    }
                }
            }
        }
        return null;
    }

    private static int[] trace(int[] parent, int goal) {
        int length = 0;
        for (int k = goal; k != -1; k = parent[k]) length++;
        int[] cells = new int[length];
        for (int k = goal, m = length - 1; k != -1; k = parent[k], m--) cells[m] = k;
        return cells;
    }
}
