package minigolf.collision;

import java.util.Arrays;
import minigolf.course.Bounds;

/**
 * The broad phase's index of a scene's shapes: a uniform grid over the course plane in which each
 * shape is listed in every cell within a ball radius of its bounding box, each cell's list cut
 * into runs under one box. Kept apart from {@link CollisionScene} because building it (cell size,
 * memory budgets, runs) is a job of its own; the sweep and the proximity queries read its arrays
 * directly in their inner loops. Immutable once built.
 */
final class ShapeGrid {
    private static final int MAX_CELLS_PER_AXIS = 512;
    /** At most this many (cell, shape) entries in the grid (32 MB of ints). */
    private static final long MAX_CELL_ENTRIES = 8_000_000;
    /** At most this many runs (28 MB); beyond, the cells grow as for the entries. */
    private static final int MAX_RUNS = 1_000_000;
    /** The most entries under one run's box. */
    static final int RUN_LENGTH = 16;

    final double originX, originY, cellSize;
    /** 1 / cellSize: a cell's index is a product, not a quotient (the queries ask four a time). */
    private final double inverseSize;
    final int columns, rows;
    /** Cell (i, j) lists shapes cellItems[cellStart[c] .. cellStart[c + 1]), c = j * columns + i. */
    final int[] cellStart, cellItems;
    /**
     * Each cell's list cut into runs: consecutive entries of one obstacle, at most {@link #RUN_LENGTH}
     * long, under one box. Cell c's runs are cellRuns[c] .. cellRuns[c + 1]; run q's entries are
     * cellItems[runStart[q] .. runStart[q + 1]); its box (6 floats, rounded outwards, so it holds
     * every box in it) lets a sweep skip the run at one test: a windmill model's 11,846 triangles
     * cost a few tests where a chord passes it.
     */
    final int[] cellRuns, runStart;
    final float[] runBoxes;
    /** Each shape's first grid column and row: a sweep tests a shape only in the first of its cells it visits. */
    final int[] firstColumn, firstRow;

    /**
     * Lists the shapes whose boxes ({@code boxes}: minX, minY, minZ, maxX, maxY, maxZ per shape)
     * are given, for a ball of radius {@code radius}; {@code obstacleOf} names each shape's
     * obstacle (a run never mixes two). The grid covers the bounds and every shape.
     */
    ShapeGrid(double[] boxes, int[] obstacleOf, double radius, Bounds bounds) {
        int shapes = boxes.length / 6;
        double minX = bounds.minX(), minY = bounds.minY(), maxX = bounds.maxX(), maxY = bounds.maxY();
        for (int s = 0; s < shapes; s++) {
            minX = Math.min(minX, boxes[6 * s]);
            minY = Math.min(minY, boxes[6 * s + 1]);
            maxX = Math.max(maxX, boxes[6 * s + 3]);
            maxY = Math.max(maxY, boxes[6 * s + 4]);
        }
        // Cells about as large as a shape is, on average.
        double area = (maxX - minX) * (maxY - minY);
        double size = Math.sqrt(area / Math.max(1, shapes));
        size = Math.max(size, Math.max(maxX - minX, maxY - minY) / MAX_CELLS_PER_AXIS);
        size = Math.max(0.05, Math.min(1.0, size));
        size = Math.max(size, Math.max(maxX - minX, maxY - minY) / MAX_CELLS_PER_AXIS);
        // A shape is listed in every cell its box touches: thousands of long walls across a course would
        // fill gigabytes. Past a budget the cells grow, so memory stays in proportion to the shapes.
        while (cellEntries(boxes, radius, minX, minY, maxX, maxY, size) > MAX_CELL_ENTRIES
                && size < Math.max(maxX - minX, maxY - minY)) {
            size *= 2;
        }
        int[] counts, items;
        int columns, rows;
        while (true) {
            columns = Math.max(1, (int) Math.ceil((maxX - minX) / size));
            rows = Math.max(1, (int) Math.ceil((maxY - minY) / size));
            int cells = columns * rows;
            counts = new int[cells + 1];
            items = null;
            for (int pass = 0; pass < 2; pass++) {
                int[] fill = pass == 1 ? Arrays.copyOf(counts, cells) : null;
                if (pass == 1) items = new int[counts[cells]];
                for (int s = 0; s < shapes; s++) {
                    int i0 = cell(boxes[6 * s] - radius, minX, 1 / size, columns), i1 = cell(boxes[6 * s + 3] + radius, minX, 1 / size, columns);
                    int j0 = cell(boxes[6 * s + 1] - radius, minY, 1 / size, rows), j1 = cell(boxes[6 * s + 4] + radius, minY, 1 / size, rows);
                    for (int j = j0; j <= j1; j++) {
                        for (int i = i0; i <= i1; i++) {
                            int c = j * columns + i;
                            if (pass == 0) counts[c + 1]++;
                            else items[fill[c]++] = s;
                        }
                    }
                }
                if (pass == 0) {
                    for (int c = 0; c < cells; c++) counts[c + 1] += counts[c];
                }
            }
            if (runs(counts, items, obstacleOf, cells, null, null) <= MAX_RUNS || size >= Math.max(maxX - minX, maxY - minY)) break;
            size *= 2;
        }
        this.cellSize = size;
        this.inverseSize = 1 / size;
        this.originX = minX;
        this.originY = minY;
        this.columns = columns;
        this.rows = rows;
        this.cellStart = counts;
        this.cellItems = items;
        int cells = columns * rows;
        cellRuns = new int[cells + 1];
        int runs = runs(counts, items, obstacleOf, cells, cellRuns, null);
        runStart = new int[runs + 1];
        runs(counts, items, obstacleOf, cells, null, runStart);
        runStart[runs] = items.length;
        runBoxes = new float[6 * runs];
        for (int q = 0; q < runs; q++) {
            for (int k = 0; k < 3; k++) {
                double low = Double.POSITIVE_INFINITY, high = Double.NEGATIVE_INFINITY;
                for (int e = runStart[q]; e < runStart[q + 1]; e++) {
                    low = Math.min(low, boxes[6 * items[e] + k]);
                    high = Math.max(high, boxes[6 * items[e] + k + 3]);
                }
                runBoxes[6 * q + k] = below(low);
                runBoxes[6 * q + k + 3] = above(high);
            }
        }
        firstColumn = new int[shapes];
        firstRow = new int[shapes];
        for (int s = 0; s < shapes; s++) {
            firstColumn[s] = column(boxes[6 * s] - radius);
            firstRow[s] = row(boxes[6 * s + 1] - radius);
        }
    }

    /**
     * Cuts each cell's entries into runs (one obstacle's, at most {@link #RUN_LENGTH}) and counts
     * them; fills each cell's first run into cellRuns and each run's first entry into runStart where
     * these are given.
     */
    private static int runs(int[] cellStart, int[] items, int[] owner, int cells, int[] cellRuns, int[] runStart) {
        int runs = 0;
        for (int c = 0; c < cells; c++) {
            if (cellRuns != null) cellRuns[c] = runs;
            for (int k = cellStart[c], end = cellStart[c + 1]; k < end; ) {
                if (runStart != null) runStart[runs] = k;
                int first = k++;
                while (k < end && k - first < RUN_LENGTH && owner[items[k]] == owner[items[first]]) k++;
                runs++;
            }
        }
        if (cellRuns != null) cellRuns[cells] = runs;
        return runs;
    }

    /** The largest float at or below x. */
    private static float below(double x) {
        float f = (float) x;
        return f > x ? Math.nextDown(f) : f;
    }

    /** The smallest float at or above x. */
    private static float above(double x) {
        float f = (float) x;
        return f < x ? Math.nextUp(f) : f;
    }

    /**
     * The cell of x along one axis: (x - origin) times the inverse cell size, floored and clamped.
     * Listing and every query use this one function, so a shape is found wherever it is listed.
     */
    private static int cell(double x, double origin, double inverseSize, int count) {
        return index((x - origin) * inverseSize, count);
    }

    /** How many (cell, shape) entries a grid of this cell size would hold, as the constructor fills it. */
    private static long cellEntries(double[] boxes, double radius, double minX, double minY, double maxX, double maxY,
                                    double size) {
        long columns = Math.max(1, (long) Math.ceil((maxX - minX) / size));
        long rows = Math.max(1, (long) Math.ceil((maxY - minY) / size));
        long entries = 0;
        for (int s = 0; s < boxes.length / 6; s++) {
            long i0 = clamp((long) Math.floor((boxes[6 * s] - radius - minX) / size), columns);
            long i1 = clamp((long) Math.floor((boxes[6 * s + 3] + radius - minX) / size), columns);
            long j0 = clamp((long) Math.floor((boxes[6 * s + 1] - radius - minY) / size), rows);
            long j1 = clamp((long) Math.floor((boxes[6 * s + 4] + radius - minY) / size), rows);
            entries += (i1 - i0 + 1) * (j1 - j0 + 1);
        }
        return entries;
    }

    private static long clamp(long i, long count) {
        return i < 0 ? 0 : Math.min(i, count - 1);
    }

    /** The grid column of x, clamped to the grid. */
    int column(double x) {
        return cell(x, originX, inverseSize, columns);
    }

    /** The grid row of y, clamped to the grid. */
    int row(double y) {
        return cell(y, originY, inverseSize, rows);
    }

    /**
     * floor(u) clamped to [0, count - 1], as (int) Math.floor(u) then clamped, without the call:
     * below 0 (or NaN) it is 0, and above it truncation is floor.
     */
    private static int index(double u, int count) {
        if (!(u >= 0)) return 0;
        return Math.min((int) u, count - 1);
    }

    /** Whether any shape is listed in the cells under the rectangle. */
    boolean anyListed(double minX, double minY, double maxX, double maxY) {
        // Shapes are listed in every cell within a ball radius of them: the centre's own cells suffice.
        int i0 = column(minX), i1 = column(maxX);
        int j0 = row(minY), j1 = row(maxY);
        for (int j = j0; j <= j1; j++) {
            int c = j * columns;
            if (cellStart[c + i1 + 1] > cellStart[c + i0]) return true;
        }
        return false;
    }

    /** How many entries the cells under the rectangle hold (a shape listed in two of them counts twice). */
    int entries(double minX, double minY, double maxX, double maxY) {
        int i0 = column(minX), i1 = column(maxX);
        int j0 = row(minY), j1 = row(maxY);
        int n = 0;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) n += cellStart[j * columns + i + 1] - cellStart[j * columns + i];
        }
        return n;
    }
}
