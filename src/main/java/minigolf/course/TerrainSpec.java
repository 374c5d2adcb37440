package minigolf.course;

import java.util.Arrays;

/** The course file's {@code terrain}: a height expression or a height grid. */
public sealed interface TerrainSpec permits TerrainSpec.HeightExpression, TerrainSpec.HeightGrid {

    /** {@code "height": "..."}: h(x, y) as an expression (see docs/course-format.md). */
    record HeightExpression(String source) implements TerrainSpec {
    }

    /**
     * {@code "grid"}: heights[j][i] is the height at (originX + i*spacing, originY + j*spacing).
     * The friction grids are optional (null) and, when present, have the same shape.
     * {@code deleted[j][i]} (optional, null when no cell is deleted) marks the cell between nodes
     * (i, j) and (i+1, j+1) as removed from the course: it counts as out of bounds.
     */
    record HeightGrid(Vec2 origin, double spacing, double[][] heights,
                      double[][] kineticFriction, double[][] staticFriction, boolean[][] deleted) implements TerrainSpec {
        /** A grid without deleted cells. */
        public HeightGrid(Vec2 origin, double spacing, double[][] heights,
                          double[][] kineticFriction, double[][] staticFriction) {
            this(origin, spacing, heights, kineticFriction, staticFriction, null);
        }

        /** Whether cell (i, j) (between nodes (i, j) and (i+1, j+1)) is deleted. */
        public boolean isDeleted(int i, int j) {
            return deleted != null && deleted[j][i];
        }

        /** Whether the point lies in a deleted cell; a point on an edge between cells belongs to the cell with the larger index. */
        public boolean isDeletedAt(double x, double y) {
            if (deleted == null) return false;
            double u = (x - origin.x()) / spacing, v = (y - origin.y()) / spacing;
            int cols = columns() - 1, rows = rows() - 1;
            if (u < 0 || v < 0 || u > cols || v > rows) return false;
            int i = Math.min((int) u, cols - 1), j = Math.min((int) v, rows - 1);
            return deleted[j][i];
        }

        /** The number of deleted cells. */
        public int deletedCount() {
            if (deleted == null) return 0;
            int n = 0;
            for (boolean[] row : deleted) for (boolean d : row) if (d) n++;
            return n;
        }
        public int columns() {
            return heights[0].length;
        }

        public int rows() {
            return heights.length;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof HeightGrid g && origin.equals(g.origin)
                    && Double.compare(spacing, g.spacing) == 0
                    && Arrays.deepEquals(heights, g.heights)
                    && Arrays.deepEquals(kineticFriction, g.kineticFriction)
                    && Arrays.deepEquals(staticFriction, g.staticFriction)
                    && Arrays.deepEquals(normalised(deleted), normalised(g.deleted));
        }

        /** An all-false mask equals no mask. */
        private static boolean[][] normalised(boolean[][] mask) {
            if (mask == null) return null;
            for (boolean[] row : mask) for (boolean d : row) if (d) return mask;
            return null;
        }

        @Override
        public int hashCode() {
            return 31 * origin.hashCode() + Arrays.deepHashCode(heights);
        }

        @Override
        public String toString() {
            return "HeightGrid[" + columns() + "x" + rows() + ", spacing=" + spacing + ", origin=" + origin + "]";
        }
    }
}
