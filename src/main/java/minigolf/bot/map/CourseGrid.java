package minigolf.bot.map;

import minigolf.bot.CancellationToken;
import minigolf.physics.World;

/**
 * The course as a grid of square cells, each free or blocked, for the bots' path searches and
 * distance fields. {@link #isBlocked(World, double, double)} is the one place that decides where a
 * ball cannot be: water (terrain below 0, or a hazard zone the ball may not enter), out of bounds,
 * and obstacles inflated by the ball's radius ({@link ObstacleFootprint}). A hazard zone the ball
 * may roll across but not rest in (the classic tracks' shallow water) is free, but counts as water
 * for the clearances ({@link #hazardClearance}), so no rest point is planned in it. A cell is blocked when its centre is, obstacles being inflated by a
 * further half cell diagonal so that a thin fence between cell centres still cuts the grid. Cells
 * blocked by trees only are marked as such ({@link #tree(int)}) for A*'s diagonal rule.
 */
public final class CourseGrid {
    /** The most cells a grid is built with (finer cells on small courses, coarser on big ones). */
    public static final int TARGET_CELLS = 40_000;
    public static final double FINEST_CELL = 0.05;

    private final World world;
    private final double minX, minY, cell;
    private final int cols, rows;
    private final boolean[] blocked;
    private final boolean[] tree;
    /** Blocked by a standing breakable brick only: the distance field may lead through it, at a cost. */
    private final boolean[] brick;
    /** Distance from each cell centre to the nearest blocked cell centre (chamfer estimate), metres. */
    private final double[] clearance;
    /** The same to the nearest lost cell (water, out of bounds): hazards, where obstacles only bounce. */
    private final double[] hazardClearance;

    private CourseGrid(World world, double cell, CancellationToken token) {
        this.world = world;
        this.cell = cell;
        this.minX = world.bounds().minX();
        this.minY = world.bounds().minY();
        this.cols = Math.max(1, (int) Math.ceil(world.bounds().width() / cell));
        this.rows = Math.max(1, (int) Math.ceil(world.bounds().depth() / cell));
        this.blocked = new boolean[cols * rows];
        this.tree = new boolean[cols * rows];
        this.brick = new boolean[cols * rows];
        boolean[] lost = new boolean[cols * rows];
        ObstacleFootprint footprint = ObstacleFootprint.of(world);
        // A cell is blocked when its centre is within the ball's radius of an obstacle, plus half a
        // cell's diagonal so that a fence between two cell centres still blocks. A ball whose radius
        // is already that long needs no margin (the blocked band round any fence, two radii and its
        // thickness, then holds a cell centre), and the margin would close the corridors it just fits
        // through: the classic tracks' ball (0.108 m) in a tile of 0.25 m has 0.033 m for its centre.
        double halfDiagonal = cell * Math.sqrt(0.5);
        double margin = world.physics().ballRadius() >= halfDiagonal ? 0 : halfDiagonal;
        for (int r = 0; r < rows; r++) {
            token.throwIfCancelled();
            for (int c = 0; c < cols; c++) {
                double x = centreX(c), y = centreY(r);
                int i = r * cols + c;
                if (lost(world, x, y)) {
                    blocked[i] = true;
                    lost[i] = true;
                    continue;
                }
                lost[i] = world.friction().restsInHazard(x, y);
                byte kind = footprint.kind(x, y, margin);
                blocked[i] = kind != ObstacleFootprint.FREE;
                tree[i] = kind == ObstacleFootprint.TREE;
                brick[i] = kind == ObstacleFootprint.BRICK;
            }
        }
        clearance = chamfer(blocked);
        hazardClearance = footprint.isEmpty() && !world.friction().hasHazards() ? clearance : chamfer(lost);
    }

    /** Two-pass 3-4 chamfer distance transform: distance to water, obstacles or the edge of the course. */
    private double[] chamfer(boolean[] blocked) {
        double[] d = new double[cols * rows];
        double straight = cell, diagonal = cell * Math.sqrt(2);
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                int i = r * cols + c;
                if (blocked[i]) { d[i] = 0; continue; }
                // The bounds count as blocked just outside the grid.
                double v = Math.min(Math.min(c + 0.5, cols - c - 0.5), Math.min(r + 0.5, rows - r - 0.5)) * cell;
                if (c > 0) v = Math.min(v, d[i - 1] + straight);
                if (r > 0) v = Math.min(v, d[i - cols] + straight);
                if (c > 0 && r > 0) v = Math.min(v, d[i - cols - 1] + diagonal);
                if (c < cols - 1 && r > 0) v = Math.min(v, d[i - cols + 1] + diagonal);
                d[i] = v;
            }
        }
        for (int r = rows - 1; r >= 0; r--) {
            for (int c = cols - 1; c >= 0; c--) {
                int i = r * cols + c;
                double v = d[i];
                if (c < cols - 1) v = Math.min(v, d[i + 1] + straight);
                if (r < rows - 1) v = Math.min(v, d[i + cols] + straight);
                if (c < cols - 1 && r < rows - 1) v = Math.min(v, d[i + cols + 1] + diagonal);
                if (c > 0 && r < rows - 1) v = Math.min(v, d[i + cols - 1] + diagonal);
                d[i] = v;
            }
        }
        return d;
    }

    /** How far the cell at (x, y) is from water, obstacles or the course's edge, in metres. */
    public double clearance(double x, double y) {
        return clearance[indexOf(x, y)];
    }

    public double clearance(int index) {
        return clearance[index];
    }

    /** How far the cell at (x, y) is from water or the course's edge (obstacles not counted), metres. */
    public double hazardClearance(double x, double y) {
        return hazardClearance[indexOf(x, y)];
    }

    public double hazardClearance(int index) {
        return hazardClearance[index];
    }

    /**
     * Whether the straight segment stays on free cells at least {@code hazardMargin} from water and
     * the edge and {@code obstacleMargin} from obstacles (sampled every half cell).
     */
    public boolean clearLine(double x0, double y0, double x1, double y1, double hazardMargin, double obstacleMargin) {
        double length = Math.hypot(x1 - x0, y1 - y0);
        int samples = Math.max(1, (int) Math.ceil(length / (0.5 * cell)));
        for (int k = 0; k <= samples; k++) {
            double f = (double) k / samples;
            int i = indexOf(x0 + f * (x1 - x0), y0 + f * (y1 - y0));
            if (blocked[i] || hazardClearance[i] < hazardMargin || clearance[i] < obstacleMargin) return false;
        }
        return true;
    }

    /**
     * Whether the straight segment between two points stays on cells at least {@code margin} from
     * water, obstacles and the edge (sampled every half cell).
     */
    public boolean clearLine(double x0, double y0, double x1, double y1, double margin) {
        double length = Math.hypot(x1 - x0, y1 - y0);
        int samples = Math.max(1, (int) Math.ceil(length / (0.5 * cell)));
        for (int k = 0; k <= samples; k++) {
            double f = (double) k / samples;
            int i = indexOf(x0 + f * (x1 - x0), y0 + f * (y1 - y0));
            if (blocked[i] || clearance[i] < margin) return false;
        }
        return true;
    }

    /** A grid with the automatic cell size. */
    public static CourseGrid of(World world, CancellationToken token) {
        double area = world.bounds().width() * world.bounds().depth();
        return new CourseGrid(world, Math.max(FINEST_CELL, Math.sqrt(area / TARGET_CELLS)), token);
    }

    public static CourseGrid of(World world, double cell, CancellationToken token) {
        if (!(cell > 0)) throw new IllegalArgumentException("cell size must be > 0, got " + cell);
        return new CourseGrid(world, cell, token);
    }

    /**
     * Whether a ball's centre cannot be at (x, y): in water, out of bounds, or within the ball's
     * radius of an obstacle. The single blocking test of all bots.
     */
    public static boolean isBlocked(World world, double x, double y) {
        return lost(world, x, y) || ObstacleFootprint.of(world).kind(x, y, 0) != ObstacleFootprint.FREE;
    }

    /**
     * Whether a ball at (x, y) is lost: in water (below 0, or a hazard zone that ends the stroke on
     * entry) or out of bounds (outside the bounds or on a deleted cell).
     */
    public static boolean lost(World world, double x, double y) {
        return !world.playArea().contains(x, y) || world.terrain().height(x, y) < 0 || world.friction().entersHazard(x, y);
    }

    public World world() {
        return world;
    }

    public int cols() {
        return cols;
    }

    public int rows() {
        return rows;
    }

    public double cell() {
        return cell;
    }

    public double centreX(int c) {
        return minX + (c + 0.5) * cell;
    }

    public double centreY(int r) {
        return minY + (r + 0.5) * cell;
    }

    public int col(double x) {
        return Math.max(0, Math.min(cols - 1, (int) Math.floor((x - minX) / cell)));
    }

    public int row(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / cell)));
    }

    public int index(int c, int r) {
        return r * cols + c;
    }

    public int indexOf(double x, double y) {
        return index(col(x), row(y));
    }

    public boolean blocked(int c, int r) {
        return c < 0 || r < 0 || c >= cols || r >= rows || blocked[r * cols + c];
    }

    public boolean blocked(int index) {
        return blocked[index];
    }

    /** Whether the cell is blocked by a standing breakable brick only (off the grid: no). */
    public boolean brick(int c, int r) {
        return c >= 0 && r >= 0 && c < cols && r < rows && brick[r * cols + c];
    }

    /** Whether the cell is blocked by a tree trunk only (not water, the edge, a wall, a box or a model). */
    public boolean tree(int index) {
        return tree[index];
    }

    /**
     * Whether a diagonal step from (c, r) by (dc, dr) is allowed: never past a blocked cell
     * (which also forbids squeezing between two), so a path cannot cut a corner of water.
     */
    public boolean diagonalAllowed(int c, int r, int dc, int dr) {
        return !blocked(c + dc, r) && !blocked(c, r + dr);
    }
}
