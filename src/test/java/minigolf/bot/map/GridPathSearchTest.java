package minigolf.bot.map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import minigolf.bot.CancellationToken;
import org.junit.jupiter.api.Test;

/** The shared A* on small hand-drawn grids. */
class GridPathSearchTest {
    /** '#' blocked; steps cost 1 or sqrt 2, no corner cutting, the straight-line heuristic. */
    private static GridPathSearch.Graph graph(String[] rows, int goalC, int goalR) {
        return new GridPathSearch.Graph() {
            boolean blocked(int c, int r) {
                return rows[r].charAt(c) == '#';
            }

            @Override
            public double stepCost(int c, int r, int dc, int dr) {
                if (blocked(c + dc, r + dr)) return Double.POSITIVE_INFINITY;
                if (dc != 0 && dr != 0 && (blocked(c + dc, r) || blocked(c, r + dr))) return Double.POSITIVE_INFINITY;
                return Math.hypot(dc, dr);
            }

            @Override
            public double heuristic(int c, int r) {
                return Math.hypot(goalC - c, goalR - r);
            }
        };
    }

    private static double length(int[] cells, int cols) {
        double total = 0;
        for (int k = 1; k < cells.length; k++) {
            total += Math.hypot(cells[k] % cols - cells[k - 1] % cols, cells[k] / cols - cells[k - 1] / cols);
        }
        return total;
    }

    @Test
    void findsTheShortestWayRoundAWall() {
        String[] rows = {
            ".....",
            ".###.",
            "..#..",
            "..#..",
        };
        // From (0, 3) to (4, 3) round the wall; no diagonal may cut a corner of it.
        int[] cells = GridPathSearch.path(5, 4, 3 * 5, 3 * 5 + 4, graph(rows, 4, 3), true, CancellationToken.none());
        assertEquals(3 * 5, cells[0]);
        assertEquals(3 * 5 + 4, cells[cells.length - 1]);
        // Up 3 to the top row, 4 along it, down 3: 10 straight steps, no diagonal can cut a corner of the wall.
        assertEquals(10, length(cells, 5), 1e-12);
    }

    @Test
    void diagonalsWhereNothingIsInTheWay() {
        String[] rows = {"....", "....", "....", "...."};
        int[] cells = GridPathSearch.path(4, 4, 0, 15, graph(rows, 3, 3), false, CancellationToken.none());
        assertArrayEquals(new int[] {0, 5, 10, 15}, cells);
    }

    @Test
    void noPathWhenTheGoalIsWalledIn() {
        String[] rows = {
            ".....",
            "..###",
            "..#..",
            "..###",
        };
        assertNull(GridPathSearch.path(5, 4, 0, 2 * 5 + 4, graph(rows, 4, 2), true, CancellationToken.none()));
    }

    @Test
    void theStartIsTheGoal() {
        assertArrayEquals(new int[] {6}, GridPathSearch.path(4, 4, 6, 6, graph(new String[] {"....", "....", "....", "...."}, 2, 1),
                true, CancellationToken.none()));
    }
}
