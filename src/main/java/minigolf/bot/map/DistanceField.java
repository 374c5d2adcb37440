package minigolf.bot.map;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.bot.CancellationToken;

/**
 * Shortest distance over free cells from every cell to the nearest of its targets, the holes (Dijkstra, 8 neighbours, no
 * corner cutting, never through a one-way gate against its way): how far a rest point really is
 * from the hole when water or walls lie between.
 * Cells close to water (not obstacles: those only bounce the ball) cost more (up to {@code 1 + NEAR_WATER_COST} times within {@code SAFE_CLEARANCE}),
 * so paths keep off the banks and rest points beside water score worse.
 */
public final class DistanceField {
    private static final double SQRT2 = Math.sqrt(2);
    public static final double SAFE_CLEARANCE = 0.5;
    public static final double NEAR_WATER_COST = 3;
    /**
     * A step into a cell that only a standing breakable brick blocks costs 1 + this times its length:
     * crossing a classic brick tile (0.25 m and the ball's diameter, 0.47 m) costs about 5 m more,
     * so the way leads through a brick where going round is longer than that (a guess, not tuned).
     */
    public static final double BRICK_COST = 10;

    private final CourseGrid grid;
    /** The one-way gates (null: none): a step against one is barred. */
    private final GateCrossings gates;
    private final double[] distance;
    /** The targets (a course's holes): any of them ends a path. */
    private final double[] targetX, targetY;

    public DistanceField(CourseGrid grid, double targetX, double targetY, CancellationToken token) {
        this(grid, targetX, targetY, token, false);
    }

    public DistanceField(CourseGrid grid, double targetX, double targetY, CancellationToken token, boolean frictionAware) {
        this(grid, new double[] {targetX}, new double[] {targetY}, token, frictionAware);
    }

    /**
     * With {@code frictionAware}, a step costs its length times the ground's kinetic friction over
     * the lowest on the course ({@link #frictionWeights}): what a shot must overcome to roll it, in
     * metres of the easiest ground. A winding grass path through dirt is then shorter than the
     * straight line across the dirt; on a course of one friction nothing changes.
     */
    public DistanceField(CourseGrid grid, double[] targetX, double[] targetY, CancellationToken token, boolean frictionAware) {
        if (targetX.length == 0 || targetX.length != targetY.length) throw new IllegalArgumentException("no targets");
        this.grid = grid;
        this.targetX = targetX.clone();
        this.targetY = targetY.clone();
        int n = grid.cols() * grid.rows();
        double[] weight = frictionAware ? frictionWeights(grid) : null;
        // Push zones make a step cheaper along the push and dearer against it; a teleport's entry is as
        // near the target as its (first) exit is.
        double[][] push = pushes(grid);
        int[][] portals = portals(grid);
        gates = GateCrossings.of(grid);
        double floor = push == null ? 0 : lowestFriction(grid) * grid.world().physics().gravity();
        distance = new double[n];
        Arrays.fill(distance, Double.POSITIVE_INFINITY);
        IndexHeap heap = new IndexHeap(n);
        for (int t = 0; t < this.targetX.length; t++) {
            double tx = this.targetX[t], ty = this.targetY[t];
            int start = grid.indexOf(tx, ty);
            double d = Math.hypot(grid.centreX(grid.col(tx)) - tx, grid.centreY(grid.row(ty)) - ty);
            if (d < distance[start]) {
                distance[start] = d;
                heap.push(start, d);
            }
        }
        int settled = 0;
        while (!heap.isEmpty()) {
            int i = heap.pop();
            if ((++settled & 4095) == 0) token.throwIfCancelled();
            if (portals != null) {
                for (int[] portal : portals) {
                    if (portal[0] != i) continue;
                    for (int k = 1; k < portal.length; k++) {
                        int j = portal[k];
                        if (distance[i] < distance[j]) {
                            distance[j] = distance[i];
                            heap.push(j, distance[i]);
                        }
                    }
                }
            }
            int c = i % grid.cols(), r = i / grid.cols();
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if (dc == 0 && dr == 0) continue;
                    int nc = c + dc, nr = r + dr;
                    // A standing brick blocks the ball but can be broken: the way leads through it at a cost.
                    boolean throughBrick = grid.brick(nc, nr);
                    if (grid.blocked(nc, nr) && !throughBrick) continue;
                    boolean diagonal = dc != 0 && dr != 0;
                    if (diagonal && !grid.diagonalAllowed(c, r, dc, dr)) continue;
                    int j = grid.index(nc, nr);
                    if (gates != null && gates.barred(j, i)) continue;
                    double nearWater = Math.max(0, 1 - grid.hazardClearance(j) / SAFE_CLEARANCE);
                    double step = (diagonal ? SQRT2 : 1) * grid.cell() * (1 + NEAR_WATER_COST * nearWater);
                    // The step between two cells on the friction of both halves.
                    if (weight != null) step *= 0.5 * (weight[i] + weight[j]);
                    if (throughBrick) step *= 1 + BRICK_COST;
                    if (push != null) {
                        // The ball goes from j to i: a push along that way pays part of the friction.
                        double ux = -dc / (diagonal ? SQRT2 : 1), uy = -dr / (diagonal ? SQRT2 : 1);
                        double along = 0.5 * ((push[0][i] + push[0][j]) * ux + (push[1][i] + push[1][j]) * uy);
                        step *= Math.max(0.1, 1 - along / floor);
                    }
                    double d = distance[i] + step;
                    if (d < distance[j]) {
                        distance[j] = d;
                        heap.push(j, d);
                    }
                }
            }
        }
    }

    /** The push (m/s²) at each cell's centre, {x[], y[]}; null on a course without push zones. */
    static double[][] pushes(CourseGrid grid) {
        var forces = grid.world().forces();
        if (forces == null || !forces.hasPushZones()) return null;
        int n = grid.cols() * grid.rows();
        double[][] push = new double[2][n];
        double[] out = new double[2];
        for (int i = 0; i < n; i++) {
            forces.push(grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols()), out);
            push[0][i] = out[0];
            push[1][i] = out[1];
        }
        return push;
    }

    /** The lowest kinetic friction of the free cells (at least 1e-3). */
    private static double lowestFriction(CourseGrid grid) {
        double lowest = Double.POSITIVE_INFINITY;
        var friction = grid.world().friction();
        for (int i = 0; i < grid.cols() * grid.rows(); i++) {
            if (!grid.blocked(i)) lowest = Math.min(lowest, friction.kinetic(grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols())));
        }
        return Math.max(Double.isFinite(lowest) ? lowest : 0, 1e-3);
    }

    /**
     * Each teleport as {exit cell, entry cells...}: the cell of its first exit (where a stroke's first
     * entry sends the ball), then the free cells whose centres its entry holds. Null without teleports.
     */
    static int[][] portals(CourseGrid grid) {
        var teleports = grid.world().teleports();
        if (teleports == null) return null;
        int[][] portals = new int[teleports.size()][];
        for (int k = 0; k < teleports.size(); k++) {
            var t = teleports.get(k);
            var exit = t.exits().get(0).position();
            List<Integer> cells = new ArrayList<>();
            cells.add(grid.indexOf(exit.x(), exit.y()));
            for (int i = 0; i < grid.cols() * grid.rows(); i++) {
                if (!grid.blocked(i) && t.entry().contains(grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols()))) cells.add(i);
            }
            portals[k] = cells.stream().mapToInt(Integer::intValue).toArray();
        }
        return portals;
    }

    /**
     * Each free cell's kinetic friction (at its centre) over the lowest of all free cells: 1 on the
     * easiest ground, 8 on dirt at 0.8 beside grass at 0.1; 1 everywhere on a one-friction course.
     */
    static double[] frictionWeights(CourseGrid grid) {
        int n = grid.cols() * grid.rows();
        double[] mu = new double[n];
        double lowest = Double.POSITIVE_INFINITY;
        var friction = grid.world().friction();
        for (int i = 0; i < n; i++) {
            if (grid.blocked(i)) continue;
            mu[i] = friction.kinetic(grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols()));
            lowest = Math.min(lowest, mu[i]);
        }
        double floor = Math.max(lowest, 1e-3);
        for (int i = 0; i < n; i++) mu[i] = grid.blocked(i) ? 1 : Math.max(mu[i], floor) / floor;
        return mu;
    }

    public CourseGrid grid() {
        return grid;
    }

    /**
     * The distance from (x, y) to the target: through the best of the nearby free cell centres,
     * or infinity when (x, y) itself is blocked or cut off.
     */
    public double at(double x, double y) {
        if (CourseGrid.isBlocked(grid.world(), x, y)) return Double.POSITIVE_INFINITY;
        int c0 = grid.col(x), r0 = grid.row(y);
        double direct = Double.POSITIVE_INFINITY;
        for (int t = 0; t < targetX.length; t++) {
            double d = Math.hypot(x - targetX[t], y - targetY[t]);
            if (c0 == grid.col(targetX[t]) && r0 == grid.row(targetY[t])) return d;
            direct = Math.min(direct, d);
        }
        double best = Double.POSITIVE_INFINITY;
        for (int r = r0 - 1; r <= r0 + 1; r++) {
            for (int c = c0 - 1; c <= c0 + 1; c++) {
                if (grid.blocked(c, r)) continue;
                double d = distance[grid.index(c, r)] + Math.hypot(x - grid.centreX(c), y - grid.centreY(r));
                if (d < best) best = d;
            }
        }
        return Math.max(best, direct);
    }

    /** The distance stored for a cell. */
    public double cellDistance(int index) {
        return distance[index];
    }

    /**
     * The shortest path from (x, y) to the nearest target as cell centres (first the start cell, last
     * the target's cell), by steepest descent of the field; empty when (x, y) is cut off.
     */
    public List<double[]> path(double x, double y) {
        List<double[]> points = new ArrayList<>();
        int i = grid.indexOf(x, y);
        if (!Double.isFinite(distance[i])) return points;
        points.add(new double[] {x, y});
        for (int guard = 0; target(i) < 0 && guard < distance.length; guard++) {
            int c = i % grid.cols(), r = i / grid.cols();
            int next = i;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    int nc = c + dc, nr = r + dr;
                    if ((dc == 0 && dr == 0) || grid.blocked(nc, nr)) continue;
                    if (dc != 0 && dr != 0 && !grid.diagonalAllowed(c, r, dc, dr)) continue;
                    int j = grid.index(nc, nr);
                    if (gates != null && gates.barred(i, j)) continue;
                    if (distance[j] < distance[next]) next = j;
                }
            }
            if (next == i) break;
            i = next;
            points.add(new double[] {grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols())});
        }
        int t = target(i);
        if (t < 0) t = nearestTarget(grid.centreX(i % grid.cols()), grid.centreY(i / grid.cols()));
        points.add(new double[] {targetX[t], targetY[t]});
        return points;
    }

    /** The target whose cell is {@code index}, or -1. */
    private int target(int index) {
        for (int t = 0; t < targetX.length; t++) if (grid.indexOf(targetX[t], targetY[t]) == index) return t;
        return -1;
    }

    private int nearestTarget(double x, double y) {
        int best = 0;
        for (int t = 1; t < targetX.length; t++) {
            if (Math.hypot(x - targetX[t], y - targetY[t]) < Math.hypot(x - targetX[best], y - targetY[best])) best = t;
        }
        return best;
    }
}
