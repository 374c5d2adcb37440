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
     */
    record HeightGrid(Vec2 origin, double spacing, double[][] heights,
                      double[][] kineticFriction, double[][] staticFriction) implements TerrainSpec {
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
                    && Arrays.deepEquals(staticFriction, g.staticFriction);
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
