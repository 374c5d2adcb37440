package minigolf.bot.planner;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.search.SpeedGuess;
import minigolf.physics.World;

/**
 * How many strokes the hole is from each resting place, in the straight-putt approximation: a
 * coarse grid of cells well clear of water (and a little clear of obstacles); a cell is one stroke from the hole when a straight
 * putt from it sees the hole clear of water and the hole is within a maximum-speed roll, k + 1
 * strokes when it so sees a cell k strokes away. Built once per course (breadth first from the
 * hole); the planner lays up to the reachable cell with the fewest strokes left. {@code robust} reads
 * it as the noiseless part of its value map ({@code minigolf.bot.noise.ValueMap}).
 */
public final class StrokePlan {
    /** At most about this many cells (coarser cells on bigger courses). */
    private static final int TARGET_CELLS = 700;
    /** A resting place this far from water at least (robust to a small error of the lay-up). */
    static final double REST_CLEARANCE = 0.3;
    /** ... and this far from obstacles (a ball beside a wall still has a shot). */
    static final double REST_OBSTACLE_CLEARANCE = 0.12;
    /** A putt's line keeps this far from water ... */
    static final double LINE_CLEARANCE = 0.1;
    /** ... and from obstacles (beyond the ball's radius, which the grid already adds). */
    static final double LINE_OBSTACLE_CLEARANCE = 0.04;

    private final World world;
    private final CourseGrid fine;
    private final double cell;
    private final int cols, rows;
    private final double minX, minY;
    private final int[] strokes;

    public StrokePlan(World world, CourseGrid fine, CancellationToken token) {
        this.world = world;
        this.fine = fine;
        double area = world.bounds().width() * world.bounds().depth();
        this.cell = Math.max(0.25, Math.sqrt(area / TARGET_CELLS));
        this.minX = world.bounds().minX();
        this.minY = world.bounds().minY();
        this.cols = Math.max(1, (int) Math.floor(world.bounds().width() / cell));
        this.rows = Math.max(1, (int) Math.floor(world.bounds().depth() / cell));
        strokes = new int[cols * rows];
        Arrays.fill(strokes, Integer.MAX_VALUE);
        List<Integer> frontier = new ArrayList<>();
        List<Integer> candidates = new ArrayList<>();
        for (int i = 0; i < strokes.length; i++) {
            if (fine.hazardClearance(x(i), y(i)) >= REST_CLEARANCE && fine.clearance(x(i), y(i)) >= REST_OBSTACLE_CLEARANCE
                    && !CourseGrid.isBlocked(world, x(i), y(i)) && canRest(world, x(i), y(i))) {
                candidates.add(i);
            }
        }
        for (int i : candidates) {
            // One putt from here: to any hole (a course may have several).
            for (var h : world.holes()) {
                if (putt(x(i), y(i), h.position().x(), h.position().y())) {
                    strokes[i] = 1;
                    frontier.add(i);
                    break;
                }
            }
        }
        for (int level = 2; !frontier.isEmpty() && level < 50; level++) {
            token.throwIfCancelled();
            List<Integer> next = new ArrayList<>();
            for (int i : candidates) {
                if (strokes[i] != Integer.MAX_VALUE) continue;
                // Up to a few hundred line tests per cell: check for a cancel often enough for 50 ms.
                token.throwIfCancelled();
                for (int j : frontier) {
                    if (putt(x(i), y(i), x(j), y(j))) {
                        strokes[i] = level;
                        next.add(i);
                        break;
                    }
                }
            }
            frontier = next;
        }
    }

    /**
     * Whether a ball can rest at (x, y) on level ground: not where a push zone or magnet pulls harder
     * than static friction holds (a classic track's downhill tiles push at 0.89 m/s^2 against 0.59):
     * a lay-up aimed there rolls on.
     */
    static boolean canRest(World world, double x, double y) {
        if (world.forces() == null || world.forces().isEmpty()) return true;
        double[] f = new double[2];
        world.forces().force(x, y, f);
        return Math.hypot(f[0], f[1]) <= world.friction().staticFriction(x, y) * world.physics().gravity();
    }

    double x(int i) {
        return minX + (i % cols + 0.5) * cell;
    }

    double y(int i) {
        return minY + (i / cols + 0.5) * cell;
    }

    int cells() {
        return strokes.length;
    }

    /** The cell's side in metres. */
    public double cell() {
        return cell;
    }

    /**
     * Strokes from (x, y) to the hole: its own cell's, or where that is no resting cell (beside a
     * wall or water), the fewest of the neighbouring cells a line from (x, y) reaches clear of
     * obstacles; Integer.MAX_VALUE when none.
     */
    public int strokesAt(double x, double y) {
        int c0 = (int) Math.floor((x - minX) / cell), r0 = (int) Math.floor((y - minY) / cell);
        if (c0 >= 0 && c0 < cols && r0 >= 0 && r0 < rows && strokes[r0 * cols + c0] != Integer.MAX_VALUE) {
            return strokes[r0 * cols + c0];
        }
        int best = Integer.MAX_VALUE;
        for (int r = r0 - 1; r <= r0 + 1; r++) {
            for (int c = c0 - 1; c <= c0 + 1; c++) {
                if (c < 0 || c >= cols || r < 0 || r >= rows) continue;
                int i = r * cols + c;
                if (strokes[i] < best && fine.clearLine(x, y, x(i), y(i), 0, 0)) best = strokes[i];
            }
        }
        return best;
    }

    /** Strokes from cell i to the hole, or Integer.MAX_VALUE when no plan reaches it. */
    int strokes(int i) {
        return strokes[i];
    }

    /** Whether a straight putt from (x0, y0) can stop at (x1, y1): a clear line within reach. */
    public boolean putt(double x0, double y0, double x1, double y1) {
        double distance = Math.hypot(x1 - x0, y1 - y0);
        if (distance > 0.99 * reach(x0, y0, x1, y1)) return false;
        return fine.clearLine(x0, y0, x1, y1, LINE_CLEARANCE, LINE_OBSTACLE_CLEARANCE);
    }

    /** How far a maximum-speed shot rolls from (x0, y0) towards a point at the height of (x1, y1). */
    double reach(double x0, double y0, double x1, double y1) {
        return SpeedGuess.maxRoll(world, x0, y0, x1, y1);
    }
}
