package minigolf.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class GridTerrainTest {
    private static final double SPACING = 0.25;

    /** Nodes of f on a 21 x 17 grid from (-2, -1). */
    private static GridTerrain sampled(java.util.function.DoubleBinaryOperator f) {
        double[][] heights = new double[17][21];
        for (int j = 0; j < 17; j++) {
            for (int i = 0; i < 21; i++) {
                heights[j][i] = f.applyAsDouble(-2 + i * SPACING, -1 + j * SPACING);
            }
        }
        return new GridTerrain(-2, -1, SPACING, heights);
    }

    @Test
    void passesThroughEveryNode() {
        GridTerrain grid = sampled((x, y) -> Math.sin(3 * x) * y);
        double[] out = new double[3];
        for (int j = 0; j < 17; j++) {
            for (int i = 0; i < 21; i++) {
                double x = -2 + i * SPACING, y = -1 + j * SPACING;
                assertEquals(Math.sin(3 * x) * y, grid.height(x, y), 1e-12);
                grid.sample(x, y, out);
                assertEquals(Math.sin(3 * x) * y, out[0], 1e-12);
            }
        }
    }

    @Test
    void reproducesAPlaneAndItsGradientExactlyAwayFromTheEdges() {
        GridTerrain grid = sampled((x, y) -> 0.3 * x - 0.2 * y + 1);
        double[] out = new double[3];
        Random random = new Random(1);
        for (int k = 0; k < 500; k++) {
            double x = -1.75 + 4.5 * random.nextDouble(), y = -0.75 + 3.5 * random.nextDouble();
            grid.sample(x, y, out);
            assertEquals(0.3 * x - 0.2 * y + 1, out[0], 1e-12);
            assertEquals(0.3, out[1], 1e-12);
            assertEquals(-0.2, out[2], 1e-12);
        }
    }

    @Test
    void gradientIsTheExactDerivativeOfTheInterpolant() {
        GridTerrain grid = sampled((x, y) -> Math.sin(2 * x) * Math.cos(y) + 0.1 * x * y);
        double[] out = new double[3];
        Random random = new Random(2);
        double step = 1e-6;
        for (int k = 0; k < 500; k++) {
            double x = -2 + 5 * random.nextDouble(), y = -1 + 4 * random.nextDouble();
            grid.sample(x, y, out);
            assertEquals((grid.height(x + step, y) - grid.height(x - step, y)) / (2 * step), out[1], 1e-7);
            assertEquals((grid.height(x, y + step) - grid.height(x, y - step)) / (2 * step), out[2], 1e-7);
            assertEquals(grid.height(x, y), out[0], 1e-15);
        }
    }

    @Test
    void gradientIsContinuousAcrossCellBoundaries() {
        GridTerrain grid = sampled((x, y) -> Math.exp(-(x * x + y * y)));
        double[] left = new double[3], right = new double[3];
        double eps = 1e-10;
        for (int i = 1; i < 20; i++) {
            double x = -2 + i * SPACING;
            grid.sample(x - eps, 0.37, left);
            grid.sample(x + eps, 0.37, right);
            assertEquals(left[1], right[1], 1e-8, "d/dx at x = " + x);
            assertEquals(left[2], right[2], 1e-8, "d/dy at x = " + x);
        }
    }

    @Test
    void approximatesASmoothSurfaceToThirdOrder() {
        GridTerrain grid = sampled((x, y) -> Math.sin(x) * Math.cos(y));
        Random random = new Random(3);
        double worst = 0;
        for (int k = 0; k < 1000; k++) {
            double x = -1.5 + 4 * random.nextDouble(), y = -0.5 + 3 * random.nextDouble();
            worst = Math.max(worst, Math.abs(grid.height(x, y) - Math.sin(x) * Math.cos(y)));
        }
        // Catmull-Rom's error is O(s^3): about 1e-3 at s = 0.25 for unit curvature.
        assertEquals(0, worst, 2e-3);
    }

    @Test
    void outsideTheGridTheEdgeIsExtendedFlat() {
        GridTerrain grid = sampled((x, y) -> x + 2 * y);
        double[] out = new double[3];
        grid.sample(5, 1, out);
        assertEquals(3 + 2, out[0], 1e-12);
        assertEquals(0, out[1]);
        grid.sample(0.5, -4, out);
        assertEquals(0.5 - 2, out[0], 1e-12);
        assertEquals(0, out[2]);
    }

    @Test
    void rejectsGridsThatCannotBeInterpolated() {
        assertThrows(IllegalArgumentException.class, () -> new GridTerrain(0, 0, 1, new double[][] {{1, 2}}));
        assertThrows(IllegalArgumentException.class, () -> new GridTerrain(0, 0, 0, new double[][] {{1, 2}, {3, 4}}));
        assertThrows(IllegalArgumentException.class, () -> new GridTerrain(0, 0, 1, new double[][] {{1, 2}, {3}}));
    }

    /**
     * Inside the grid, height and sample take a path without index clamps; it must give the
     * clamped path's values bit for bit (saved games replay strokes to the bit).
     */
    @Test
    void theInteriorPathIsBitForBitTheClampedOne() {
        GridTerrain grid = sampled((x, y) -> Math.sin(3 * x) * Math.cos(2 * y) + 0.1 * x * y);
        Random random = new Random(5);
        double[] fast = new double[3], clamped = new double[3];
        int interior = 0;
        for (int k = 0; k < 20_000; k++) {
            double x = -2.3 + 5.6 * random.nextDouble(), y = -1.3 + 4.6 * random.nextDouble();
            double u = (x + 2) / SPACING, v = (y + 1) / SPACING;
            if (u < 0 || v < 0 || u > 20 || v > 16) continue;
            int i = Math.min((int) u, 19), j = Math.min((int) v, 15);
            double tx = u - i, ty = v - j;
            grid.sample(x, y, fast);
            grid.clampedSample(i, j, tx, ty, clamped);
            if (i >= 1 && i + 2 < 21 && j >= 1 && j + 2 < 17) interior++;
            assertEquals(Double.doubleToRawLongBits(clamped[0]), Double.doubleToRawLongBits(fast[0]));
            assertEquals(Double.doubleToRawLongBits(clamped[1] / SPACING), Double.doubleToRawLongBits(fast[1]));
            assertEquals(Double.doubleToRawLongBits(clamped[2] / SPACING), Double.doubleToRawLongBits(fast[2]));
            assertEquals(Double.doubleToRawLongBits(grid.clampedHeight(i, j, tx, ty)),
                    Double.doubleToRawLongBits(grid.height(x, y)));
        }
        assertTrue(interior > 10_000, interior + " interior points");
    }
}
