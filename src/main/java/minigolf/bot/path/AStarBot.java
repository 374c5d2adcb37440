package minigolf.bot.path;

import java.util.List;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.search.Aim;
import minigolf.bot.search.SearchBot;
import minigolf.bot.search.Target;

/**
 * {@code astar}: A* from the ball to the hole on the course grid, then one shot per waypoint:
 * each stroke aims (a few corrected shots) at the next critical point, the last at the hole.
 */
public final class AStarBot extends SearchBot {
    private final int shotsPerWaypoint;

    public AStarBot() {
        this(12);
    }

    public AStarBot(int shotsPerWaypoint) {
        this.shotsPerWaypoint = shotsPerWaypoint;
    }

    @Override
    public String name() {
        return "astar";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        CourseMaps maps = maps(request);
        sim.phase("A*");
        Target hole = Target.hole(sim, request.ballX(), request.ballY());
        List<double[]> points = Waypoints.find(maps.grid(), request.ballX(), request.ballY(), hole.x(), hole.y(),
                request.token());
        sim.phase("aim");
        sim.showPlan(Waypoints.route(request.ballX(), request.ballY(), points, hole.x(), hole.y()));
        Target next = points.size() <= 1 ? hole
                : Target.point(request.ballX(), request.ballY(), points.get(0)[0], points.get(0)[1], 0.3);
        Aim.Aimed aimed = Aim.at(sim, next, shotsPerWaypoint);
        return aimed != null ? aimed.shot() : directGuess(request.world(), request.ballX(), request.ballY());
    }
}
