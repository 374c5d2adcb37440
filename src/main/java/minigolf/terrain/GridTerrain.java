package minigolf.terrain;

import minigolf.course.TerrainSpec.HeightGrid;

/**
 * Heights on a regular grid, interpolated with bicubic convolution (Catmull-Rom, Keys a = -1/2):
 * it passes through every node, is C1-continuous, and its gradient is the exact derivative of
 * the interpolant. Outside the grid the edge values are extended (the surface is clamped).
 */
public final class GridTerrain implements Terrain {
    private final double originX;
    private final double originY;
    private final double spacing;
    private final int columns;
    private final int rows;
    /** Row-major copy of the heights: heights[j * columns + i] is the node at (i, j). */
    private final double[] heights;

    public GridTerrain(HeightGrid grid) {
        this(grid.origin().x(), grid.origin().y(), grid.spacing(), grid.heights());
    }

    public GridTerrain(double originX, double originY, double spacing, double[][] nodeHeights) {
        if (nodeHeights.length < 2 || nodeHeights[0].length < 2) {
            throw new IllegalArgumentException("a height grid needs at least 2x2 nodes");
        }
        if (!(spacing > 0)) {
            throw new IllegalArgumentException("grid spacing must be > 0, got " + spacing);
        }
        this.originX = originX;
        this.originY = originY;
        this.spacing = spacing;
        this.rows = nodeHeights.length;
        this.columns = nodeHeights[0].length;
        this.heights = new double[rows * columns];
        for (int j = 0; j < rows; j++) {
            if (nodeHeights[j].length != columns) {
                throw new IllegalArgumentException("grid row " + j + " has " + nodeHeights[j].length
                        + " values, expected " + columns);
            }
            System.arraycopy(nodeHeights[j], 0, heights, j * columns, columns);
        }
    }

    public double maxX() {
        return originX + (columns - 1) * spacing;
    }

    public double maxY() {
        return originY + (rows - 1) * spacing;
    }

    @Override
    public double height(double x, double y) {
        double u = clamp((x - originX) / spacing, columns - 1);
        double v = clamp((y - originY) / spacing, rows - 1);
        int i = cell(u, columns);
        int j = cell(v, rows);
        double tx = u - i, ty = v - j;
        if (i >= 1 && i + 2 < columns && j >= 1 && j + 2 < rows) return interiorHeight(i, j, tx, ty);
        return clampedHeight(i, j, tx, ty);
    }

    /**
     * The height in a cell whose 4 x 4 nodes all lie inside the grid: the same sums in the same
     * order as {@link #clampedHeight}, so bit for bit the same value, without the index clamps.
     */
    private double interiorHeight(int i, int j, double tx, double ty) {
        double wx0 = w0(tx), wx1 = w1(tx), wx2 = w2(tx), wx3 = w3(tx);
        int r = (j - 1) * columns + i - 1;
        double h = 0;
        h += w0(ty) * (wx0 * heights[r] + wx1 * heights[r + 1] + wx2 * heights[r + 2] + wx3 * heights[r + 3]);
        r += columns;
        h += w1(ty) * (wx0 * heights[r] + wx1 * heights[r + 1] + wx2 * heights[r + 2] + wx3 * heights[r + 3]);
        r += columns;
        h += w2(ty) * (wx0 * heights[r] + wx1 * heights[r + 1] + wx2 * heights[r + 2] + wx3 * heights[r + 3]);
        r += columns;
        h += w3(ty) * (wx0 * heights[r] + wx1 * heights[r + 1] + wx2 * heights[r + 2] + wx3 * heights[r + 3]);
        return h;
    }

    /** The height in cell (i, j) at (tx, ty), the nodes' indices clamped to the grid. */
    double clampedHeight(int i, int j, double tx, double ty) {
        double h = 0;
        for (int m = 0; m < 4; m++) {
            int row = clampIndex(j - 1 + m, rows) * columns;
            double sum = w0(tx) * heights[row + clampIndex(i - 1, columns)] + w1(tx) * heights[row + i]
                    + w2(tx) * heights[row + clampIndex(i + 1, columns)]
                    + w3(tx) * heights[row + clampIndex(i + 2, columns)];
            h += weight(m, ty) * sum;
        }
        return h;
    }

    @Override
    public void sample(double x, double y, double[] out) {
        double rawU = (x - originX) / spacing;
        double rawV = (y - originY) / spacing;
        double u = clamp(rawU, columns - 1);
        double v = clamp(rawV, rows - 1);
        int i = cell(u, columns);
        int j = cell(v, rows);
        double tx = u - i, ty = v - j;
        if (i >= 1 && i + 2 < columns && j >= 1 && j + 2 < rows) {
            interiorSample(i, j, tx, ty, out);
        } else {
            clampedSample(i, j, tx, ty, out);
        }
        // Outside the grid the surface is clamped, so the gradient across the edge is zero.
        out[1] = rawU == u ? out[1] / spacing : 0;
        out[2] = rawV == v ? out[2] / spacing : 0;
    }

    /**
     * Height and gradient (in grid units) in a cell whose 4 x 4 nodes lie inside the grid: the
     * same sums in the same order as {@link #clampedSample}, so bit for bit the same values,
     * without the index clamps and the weight switches (terrain samples are most of a step's cost
     * on a grid).
     */
    private void interiorSample(int i, int j, double tx, double ty, double[] out) {
        double wx0 = w0(tx), wx1 = w1(tx), wx2 = w2(tx), wx3 = w3(tx);
        double dx0 = d0(tx), dx1 = d1(tx), dx2 = d2(tx), dx3 = d3(tx);
        double h = 0, hx = 0, hy = 0;
        int r = (j - 1) * columns + i - 1;
        for (int m = 0; m < 4; m++, r += columns) {
            double f0 = heights[r], f1 = heights[r + 1], f2 = heights[r + 2], f3 = heights[r + 3];
            double along = wx0 * f0 + wx1 * f1 + wx2 * f2 + wx3 * f3;
            double slope = dx0 * f0 + dx1 * f1 + dx2 * f2 + dx3 * f3;
            double wy = m == 0 ? w0(ty) : m == 1 ? w1(ty) : m == 2 ? w2(ty) : w3(ty);
            double dy = m == 0 ? d0(ty) : m == 1 ? d1(ty) : m == 2 ? d2(ty) : d3(ty);
            h += wy * along;
            hx += wy * slope;
            hy += dy * along;
        }
        out[0] = h;
        out[1] = hx;
        out[2] = hy;
    }

    /** Height and gradient (in grid units) in cell (i, j) at (tx, ty), the nodes' indices clamped to the grid. */
    void clampedSample(int i, int j, double tx, double ty, double[] out) {
        double wx0 = w0(tx), wx1 = w1(tx), wx2 = w2(tx), wx3 = w3(tx);
        double dx0 = d0(tx), dx1 = d1(tx), dx2 = d2(tx), dx3 = d3(tx);
        int c0 = clampIndex(i - 1, columns), c2 = clampIndex(i + 1, columns), c3 = clampIndex(i + 2, columns);
        double h = 0, hx = 0, hy = 0;
        for (int m = 0; m < 4; m++) {
            int row = clampIndex(j - 1 + m, rows) * columns;
            double f0 = heights[row + c0], f1 = heights[row + i], f2 = heights[row + c2], f3 = heights[row + c3];
            double along = wx0 * f0 + wx1 * f1 + wx2 * f2 + wx3 * f3;
            double slope = dx0 * f0 + dx1 * f1 + dx2 * f2 + dx3 * f3;
            double wy = weight(m, ty);
            h += wy * along;
            hx += wy * slope;
            hy += derivativeWeight(m, ty) * along;
        }
        out[0] = h;
        out[1] = hx;
        out[2] = hy;
    }

    private static double clamp(double u, int max) {
        return u < 0 ? 0 : (u > max ? max : u);
    }

    /** The cell index of a clamped grid coordinate; the last node belongs to the last cell. */
    private static int cell(double u, int count) {
        int i = (int) u;
        return i >= count - 1 ? count - 2 : i;
    }

    private static int clampIndex(int i, int count) {
        return i < 0 ? 0 : (i >= count ? count - 1 : i);
    }

    private static double weight(int m, double t) {
        switch (m) {
            case 0: return w0(t);
            case 1: return w1(t);
            case 2: return w2(t);
            default: return w3(t);
        }
    }

    private static double derivativeWeight(int m, double t) {
        switch (m) {
            case 0: return d0(t);
            case 1: return d1(t);
            case 2: return d2(t);
            default: return d3(t);
        }
    }

    // Catmull-Rom weights of the four nodes around a cell, and their derivatives in t.
    private static double w0(double t) { return 0.5 * (((-t + 2) * t - 1) * t); }
    private static double w1(double t) { return 0.5 * ((3 * t - 5) * t * t + 2); }
    private static double w2(double t) { return 0.5 * (((-3 * t + 4) * t + 1) * t); }
    private static double w3(double t) { return 0.5 * ((t - 1) * t * t); }
    private static double d0(double t) { return 0.5 * ((-3 * t + 4) * t - 1); }
    private static double d1(double t) { return 0.5 * (9 * t - 10) * t; }
    private static double d2(double t) { return 0.5 * ((-9 * t + 8) * t + 1); }
    private static double d3(double t) { return 0.5 * (3 * t - 2) * t; }
}
