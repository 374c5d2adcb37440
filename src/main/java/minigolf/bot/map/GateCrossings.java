package minigolf.bot.map;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Obstacle;
import minigolf.course.Segments;

/**
 * The one-way gates as the grid's searches see them: a step between two cell centres that crosses a
 * gate's line against its pass side is barred (the ball would bounce off), one along it is free. The
 * gates are thin, so the grid does not block their cells ({@link ObstacleFootprint} leaves them out);
 * without this a route could lead back through a gate the wrong way, and the planner would play
 * towards a face that only bounces it back.
 */
final class GateCrossings {
    /** Per gate: ax, ay, bx, by, nx, ny (unit pass normal). */
    private final double[][] gates;
    /** Cells with a gate within reach of a step from them (only those are tested). */
    private final boolean[] near;
    private final CourseGrid grid;

    private GateCrossings(CourseGrid grid, double[][] gates) {
        this.grid = grid;
        this.gates = gates;
        near = new boolean[grid.cols() * grid.rows()];
        double reach = 2 * grid.cell();
        for (double[] g : gates) {
            int c0 = grid.col(Math.min(g[0], g[2]) - reach), c1 = grid.col(Math.max(g[0], g[2]) + reach);
            int r0 = grid.row(Math.min(g[1], g[3]) - reach), r1 = grid.row(Math.max(g[1], g[3]) + reach);
            for (int r = r0; r <= r1; r++) {
                for (int c = c0; c <= c1; c++) near[grid.index(c, r)] = true;
            }
        }
    }

    /** The gates of the grid's course, or null when it has none. */
    static GateCrossings of(CourseGrid grid) {
        List<double[]> list = new ArrayList<>();
        for (Obstacle o : grid.world().course().obstacles()) {
            if (!(o instanceof Obstacle.Gate g)) continue;
            var n = g.passNormal();
            list.add(new double[] {g.from().x(), g.from().y(), g.to().x(), g.to().y(), n.x(), n.y()});
        }
        return list.isEmpty() ? null : new GateCrossings(grid, list.toArray(new double[0][]));
    }

    /** Whether a ball rolling from the centre of cell {@code from} to that of cell {@code to} is stopped by a gate. */
    boolean barred(int from, int to) {
        if (!near[from] && !near[to]) return false;
        double x0 = grid.centreX(from % grid.cols()), y0 = grid.centreY(from / grid.cols());
        double x1 = grid.centreX(to % grid.cols()), y1 = grid.centreY(to / grid.cols());
        for (double[] g : gates) {
            if ((x1 - x0) * g[4] + (y1 - y0) * g[5] >= 0) continue;
            if (segmentsCross(x0, y0, x1, y1, g[0], g[1], g[2], g[3])) return true;
        }
        return false;
    }

    /** Whether segment p0-p1 meets segment a-b (touching counts). */
    static boolean segmentsCross(double x0, double y0, double x1, double y1, double ax, double ay, double bx, double by) {
        double d1 = Segments.side(ax, ay, bx, by, x0, y0), d2 = Segments.side(ax, ay, bx, by, x1, y1);
        double d3 = Segments.side(x0, y0, x1, y1, ax, ay), d4 = Segments.side(x0, y0, x1, y1, bx, by);
        return d1 * d2 <= 0 && d3 * d4 <= 0 && !(d1 == 0 && d2 == 0);
    }
}
