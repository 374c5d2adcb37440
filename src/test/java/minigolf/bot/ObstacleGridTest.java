package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.DistanceField;
import minigolf.bot.path.AStar;
import minigolf.course.CourseException;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Obstacles in the bots' grid: walls, boxes and trees block, inflated by the ball's radius. */
class ObstacleGridTest {
    private static final double R = 0.02135;

    /**
     * Flat 6 x 6 m: a wall along x = 0 from y = -3 to 2 (0.1 m thick, a gap above y = 2.05), a
     * tree at (-1.5, -1.5), a box round (1.5, -1.5), a box raised 0.5 m above the ground (the ball
     * rolls under it) round (1.5, 1.5) and a thin fence (thickness 0) from (-2.5, 1) to (-0.5, 1).
     */
    static World course() {
        String json = """
            {"format": 1, "name": "grid test", "terrain": {"height": "0.1"},
             "bounds": {"min": [-3, -3], "max": [3, 3]},
             "physics": {"kineticFriction": 0.1, "staticFriction": 0.2},
             "start": [-2, -2], "hole": {"position": [2, -2], "radius": 0.1},
             "obstacles": [
               {"type": "wall", "from": [0, -3], "to": [0, 2], "thickness": 0.1, "height": 0.2},
               {"type": "tree", "position": [-1.5, -1.5], "radius": 0.2, "height": 2},
               {"type": "box", "min": [1.3, -1.7, 0], "max": [1.7, -1.3, 0.3]},
               {"type": "box", "min": [1.3, 1.3, 0.6], "max": [1.7, 1.7, 0.9]},
               {"type": "wall", "from": [-2.5, 1], "to": [-0.5, 1], "thickness": 0, "height": 0.2}
             ]}""";
        try {
            return World.parse(json, "grid-test.json");
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    @Test
    void obstaclesBlockTheBallsCentreWithinItsRadius() {
        World w = course();
        // The wall's face is at x = 0.05: a centre closer than the ball's radius touches it.
        assertTrue(CourseGrid.isBlocked(w, 0, 0));
        assertTrue(CourseGrid.isBlocked(w, 0.05 + 0.99 * R, 0));
        assertFalse(CourseGrid.isBlocked(w, 0.05 + 1.01 * R, 0));
        // Its square end reaches y = 2.05.
        assertTrue(CourseGrid.isBlocked(w, 0, 2.05 + 0.99 * R));
        assertFalse(CourseGrid.isBlocked(w, 0, 2.05 + 1.01 * R));
        // The trunk (radius 0.2), the box's inside and its edge zone.
        assertTrue(CourseGrid.isBlocked(w, -1.5 + 0.2 + 0.99 * R, -1.5));
        assertFalse(CourseGrid.isBlocked(w, -1.5 + 0.2 + 1.01 * R, -1.5));
        assertTrue(CourseGrid.isBlocked(w, 1.5, -1.5));
        assertTrue(CourseGrid.isBlocked(w, 1.7 + 0.99 * R, -1.5));
        assertFalse(CourseGrid.isBlocked(w, 1.7 + 1.01 * R, -1.5));
        // The raised box's underside (0.5 m above the ground) leaves room for a 4.3 cm ball.
        assertFalse(CourseGrid.isBlocked(w, 1.5, 1.5));
        // The thin fence blocks within a ball radius of its line.
        assertTrue(CourseGrid.isBlocked(w, -1.5, 1 + 0.99 * R));
        assertFalse(CourseGrid.isBlocked(w, -1.5, 1 + 1.01 * R));
    }

    @Test
    void aStarMarksTreesAsTreesAndTheRestAsWalls() {
        World w = course();
        CourseGrid grid = CourseGrid.of(w, 0.05, CancellationToken.none());
        AStar astar = AStar.of(grid);
        assertEquals(AStar.TREE, astar.kind(grid.col(-1.5), grid.row(-1.5)));
        assertEquals(AStar.WALL, astar.kind(grid.col(0), grid.row(0)));
        assertEquals(AStar.WALL, astar.kind(grid.col(1.5), grid.row(-1.5)));
        assertEquals(AStar.WALL, astar.kind(grid.col(-1.5), grid.row(1)));
        assertEquals(AStar.FREE, astar.kind(grid.col(1.5), grid.row(1.5)));
        assertEquals(AStar.FREE, astar.kind(grid.col(-2), grid.row(-2)));
    }

    @Test
    void theAStarPathGoesRoundTheWallsEnd() {
        World w = course();
        CourseGrid grid = CourseGrid.of(w, 0.05, CancellationToken.none());
        List<int[]> path = AStar.of(grid).path(grid.col(-2), grid.row(-2), grid.col(2), grid.row(-2),
                CancellationToken.none());
        assertFalse(path.isEmpty());
        // Through the gap above the wall's end (y > 2.05), never through a blocked cell.
        assertTrue(path.stream().anyMatch(c -> grid.centreY(c[1]) > 2.05 + R));
        assertTrue(path.stream().noneMatch(c -> grid.blocked(c[0], c[1])));
        // The distance field agrees: no way is shorter than over the wall's end, 2 hypot(2, 4.05) = 9.03 m.
        DistanceField field = new DistanceField(grid, 2, -2, CancellationToken.none());
        double around = field.at(-2, -2);
        assertTrue(Double.isFinite(around) && around > 2 * Math.hypot(2, 4.05), "" + around);
    }

    @Test
    void aThinFenceCutsTheGridEvenOnCoarseCells() {
        World w = course();
        // 0.3 m cells: the fence (no thickness) lies between cell centres, yet no column crosses it.
        CourseGrid grid = CourseGrid.of(w, 0.3, CancellationToken.none());
        for (double x = -2.4; x <= -0.6; x += 0.1) {
            int c = grid.col(x);
            boolean cut = false;
            for (int r = grid.row(0.7); r <= grid.row(1.3); r++) cut |= grid.blocked(c, r);
            assertTrue(cut, "column at x = " + x);
        }
    }

    @Test
    void deletedTerrainCellsAreLostLikeTheOutsideOfTheBounds() {
        // The physics test's flat 10 x 4 m grid with the cell column 6 <= x < 7 deleted.
        World world = World.of(minigolf.physics.DeletedCellsTest.flat(6, 10));
        assertFalse(CourseGrid.lost(world, 5.9, 2));
        assertTrue(CourseGrid.lost(world, 6.5, 2));
        assertTrue(CourseGrid.isBlocked(world, 6.5, 2));
        assertFalse(CourseGrid.lost(world, 7.1, 2));
    }
}
