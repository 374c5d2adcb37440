package minigolf.bot.path;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.CancellationToken;
import minigolf.bot.map.CourseGrid;

/**
 * The critical points of an A* path: from each point, the farthest later path cell still in a
 * clear straight line (string pulling), so what remains are the corners and corridor ends.
 */
public final class Waypoints {
    private Waypoints() {
    }

    /** The whole route for drawing: the ball, the waypoints, and the hole (once). */
    public static List<double[]> route(double ballX, double ballY, List<double[]> waypoints, double holeX, double holeY) {
        List<double[]> route = new ArrayList<>();
        route.add(new double[] {ballX, ballY});
        route.addAll(waypoints);
        double[] last = route.get(route.size() - 1);
        if (last[0] != holeX || last[1] != holeY) route.add(new double[] {holeX, holeY});
        return route;
    }

    /** Points (x, y) after the ball up to and including the hole; empty when the hole is cut off. */
    public static List<double[]> find(CourseGrid grid, double ballX, double ballY, double holeX, double holeY,
                                      CancellationToken token) {
        AStar astar = AStar.of(grid);
        List<int[]> cells = astar.path(grid.col(ballX), grid.row(ballY), grid.col(holeX), grid.row(holeY), token);
        List<double[]> points = new ArrayList<>();
        if (cells.isEmpty()) return points;
        double cx = ballX, cy = ballY;
        int i = 0;
        while (true) {
            token.throwIfCancelled();
            if (grid.clearLine(cx, cy, holeX, holeY, 0)) break;
            int farthest = i + 1;
            for (int k = cells.size() - 1; k > i; k--) {
                double x = grid.centreX(cells.get(k)[0]), y = grid.centreY(cells.get(k)[1]);
                if (grid.clearLine(cx, cy, x, y, 0)) {
                    farthest = k;
                    break;
                }
            }
            if (farthest >= cells.size()) break;
            cx = grid.centreX(cells.get(farthest)[0]);
            cy = grid.centreY(cells.get(farthest)[1]);
            points.add(new double[] {cx, cy});
            i = farthest;
        }
        points.add(new double[] {holeX, holeY});
        return points;
    }
}
