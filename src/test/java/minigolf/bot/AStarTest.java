package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.DistanceField;
import minigolf.bot.path.AStar;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** A*'s diagonal rules and the distance field around water. */
class AStarTest {
    private static final byte F = AStar.FREE, W = AStar.WALL, T = AStar.TREE;

    /** 2x2 grid, from the cell (0,0) to (1,1); the other two cells are given. */
    private static List<int[]> diagonalCase(byte right, byte above) {
        return new AStar(2, 2, new byte[] {F, right, above, F}).path(0, 0, 1, 1, CancellationToken.none());
    }

    @Test
    void aDiagonalStepMayNotPassAWall() {
        List<int[]> path = diagonalCase(W, F);
        assertEquals(3, path.size());
        assertArrayEquals(new int[] {0, 1}, path.get(1));
    }

    @Test
    void aDiagonalStepMayNotPassBetweenTwoWalls() {
        assertTrue(diagonalCase(W, W).isEmpty());
    }

    @Test
    void aDiagonalStepMayPassBetweenTwoTrees() {
        List<int[]> path = diagonalCase(T, T);
        assertEquals(2, path.size());
        assertArrayEquals(new int[] {1, 1}, path.get(1));
        assertEquals(2, diagonalCase(T, F).size());
    }

    @Test
    void findsTheShortestWayAroundAWall() {
        // 5x3 grid, a wall across x = 2 except at the top row: the path goes over the top.
        byte[] k = new byte[15];
        k[2] = W;
        k[5 + 2] = W;
        List<int[]> path = new AStar(5, 3, k).path(0, 0, 4, 0, CancellationToken.none());
        assertTrue(path.stream().anyMatch(c -> c[0] == 2 && c[1] == 2));
        assertTrue(path.stream().noneMatch(c -> k[c[1] * 5 + c[0]] == W));
    }

    @Test
    void theDistanceFieldGoesAroundTheLake() {
        World lake = BenchCourses.load("lake-bowl");
        CourseGrid grid = CourseGrid.of(lake, CancellationToken.none());
        DistanceField field = new DistanceField(grid, 4, 1, CancellationToken.none());
        double straight = Math.hypot(4 + 3, 1);
        double around = field.at(-3, 0);
        // The straight line passes 0.42 m from the centre, inside the 0.918 m lake: the way round is longer.
        assertTrue(around > straight + 0.1, around + " vs " + straight);
        assertEquals(Double.POSITIVE_INFINITY, field.at(0, 0));
        // On open ground far from water the field is the straight distance (within a cell or two).
        DistanceField flat = new DistanceField(CourseGrid.of(BenchCourses.load("flat-7m"), CancellationToken.none()),
                3.5, 0, CancellationToken.none());
        assertEquals(7, flat.at(-3.5, 0), 0.15);
    }
}
