package minigolf.render;

import minigolf.course.Bounds;

/**
 * The terrain grid's cells [i0, i1) x [j0, j1) that meet a world box, and whether the box reaches
 * the course's edge (the skirts may then show in it): what the balls' shadows redraw. Plain
 * arithmetic, no GL.
 *
 * @param i0 first column of cells, i1 one past the last (empty when i1 <= i0)
 * @param j0 first row of cells, j1 one past the last
 * @param edge whether the box touches or crosses the course's bounds
 */
record CellRange(int i0, int i1, int j0, int j1, boolean edge) {
    /**
     * The cells of a grid of {@code nx} x {@code ny} cells over {@code bounds} that meet the box
     * (min x, y, z, max x, y, z), widened by {@code margin} cells each way and clipped to the grid.
     */
    static CellRange of(Bounds bounds, int nx, int ny, float[] box, int margin) {
        int i0 = (int) Math.max(0, Math.floor((box[0] - bounds.minX()) / bounds.width() * nx) - margin);
        int i1 = (int) Math.min(nx, Math.ceil((box[3] - bounds.minX()) / bounds.width() * nx) + margin);
        int j0 = (int) Math.max(0, Math.floor((box[1] - bounds.minY()) / bounds.depth() * ny) - margin);
        int j1 = (int) Math.min(ny, Math.ceil((box[4] - bounds.minY()) / bounds.depth() * ny) + margin);
        boolean edge = box[0] <= bounds.minX() || box[3] >= bounds.maxX() || box[1] <= bounds.minY() || box[4] >= bounds.maxY();
        return new CellRange(i0, i1, j0, j1, edge);
    }

    /** Whether some rows meet the box. */
    boolean hasRows() {
        return j1 > j0;
    }
}
