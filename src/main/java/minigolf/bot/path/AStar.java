package minigolf.bot.path;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.GridPathSearch;

/**
 * A* on a grid of cells, as in the seed: Manhattan heuristic, 8 neighbours. A diagonal step may
 * not pass a wall (so never between two walls either); it may pass trees, even between two.
 * Water and the course's edge count as walls. The search is the shared {@link GridPathSearch}.
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
        int[] cells = GridPathSearch.path(cols, rows, startR * cols + startC, goalR * cols + goalC, new GridPathSearch.Graph() {
            @Override
            public double stepCost(int c, int r, int dc, int dr) {
                if (kind(c + dc, r + dr) != FREE) return Double.POSITIVE_INFINITY;
                boolean diagonal = dc != 0 && dr != 0;
                if (diagonal && !diagonalAllowed(c, r, dc, dr)) return Double.POSITIVE_INFINITY;
                return diagonal ? Math.sqrt(2) : 1;
            }

            @Override
            public double heuristic(int c, int r) {
                return Math.abs(goalC - c) + Math.abs(goalR - r);
            }
        }, false, token);
        List<int[]> path = new ArrayList<>();
        if (cells != null) for (int i : cells) path.add(new int[] {i % cols, i / cols});
        return path;
    }
}
