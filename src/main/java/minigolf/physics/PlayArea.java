package minigolf.physics;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.TerrainSpec;

/**
 * Where the ball is in play: inside the bounds and not over a deleted terrain cell. A ball that
 * leaves it is out of bounds; the stroke locates the crossing by the same bisection for both.
 */
public final class PlayArea {
    private final Bounds bounds;
    /** The grid whose deleted cells are holes in the course, or null when none is deleted. */
    private final TerrainSpec.HeightGrid grid;

    public PlayArea(Course course) {
        this.bounds = course.bounds();
        this.grid = course.terrain() instanceof TerrainSpec.HeightGrid g && g.deletedCount() > 0 ? g : null;
    }

    public boolean contains(double x, double y) {
        return bounds.contains(x, y) && (grid == null || !grid.isDeletedAt(x, y));
    }

    /**
     * How far (m) (x, y) lies inside the bounds' rectangle, negative outside: a guess at where a path
     * leaves them, between points on either side (deleted cells are not counted).
     */
    public double depthInside(double x, double y) {
        return Math.min(Math.min(x - bounds.minX(), bounds.maxX() - x), Math.min(y - bounds.minY(), bounds.maxY() - y));
    }

    /** Whether some cells are deleted (the area is not just the bounds' rectangle). */
    public boolean hasDeletedCells() {
        return grid != null;
    }
}
