package minigolf.bot.path;

import java.util.List;
import java.util.SplittableRandom;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseMaps;
import minigolf.bot.search.NewtonSolver;
import minigolf.bot.search.SearchBot;
import minigolf.bot.search.SwarmSolver;
import minigolf.bot.search.Target;

/**
 * {@code astar-newton} and {@code astar-swarm}: the solver aims at the A* path's critical points
 * in turn, each solution seeding the next (its speed scaled for the longer distance), the last
 * one at the hole. If the hole is not reached, the solution for the farthest critical point
 * reached is played (a lay-up along the path), else the best shot seen.
 */
public final class GuidedBot extends SearchBot {
    /** Which solver follows the path. */
    public enum Solver { NEWTON, SWARM }

    private final Solver solver;
    private final NewtonSolver newton = new NewtonSolver();
    private final SwarmSolver swarm = new SwarmSolver();

    public GuidedBot(Solver solver) {
        this.solver = solver;
    }

    @Override
    public String name() {
        return solver == Solver.NEWTON ? "astar-newton" : "astar-swarm";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        CourseMaps maps = maps(request);
        sim.phase("A*");
        double bx = request.ballX(), by = request.ballY();
        Target hole = Target.hole(sim, bx, by);
        List<double[]> points = Waypoints.find(maps.grid(), bx, by, hole.x(), hole.y(), request.token());
        if (points.isEmpty()) points = List.of(new double[] {hole.x(), hole.y()});
        sim.showPlan(Waypoints.route(request.ballX(), request.ballY(), points, hole.x(), hole.y()));
        SplittableRandom random = new SplittableRandom(request.seed());
        Shot seed = directGuess(request.world(), bx, by);
        double holeDistance = hole.distance();
        Shot farthest = null;
        for (int k = 0; k < points.size(); k++) {
            double[] p = points.get(k);
            boolean last = k == points.size() - 1;
            Target target = last ? hole : Target.point(bx, by, p[0], p[1], 0.3);
            if (k == 0) {
                seed = Shot.polar(target.angle(), directGuess(request.world(), bx, by).speed()
                        * Math.sqrt(target.distance() / Math.max(holeDistance, 1e-6)));
            } else {
                double[] previous = points.get(k - 1);
                seed = nextSeed(seed, bx, by, previous[0], previous[1], target.x(), target.y());
            }
            sim.phase((last ? "hole" : "point " + (k + 1)) + " (" + name() + ")");
            Shot solution = solver == Solver.NEWTON
                    ? newton.solve(sim, target, sim.limit(seed), random)
                    : swarm.solve(sim, target, sim.limit(seed), Math.toRadians(15), 0.2, random);
            if (solution == null) break;
            if (last) return solution;
            farthest = solution;
            seed = solution;
        }
        if (farthest != null) return farthest;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(request.world(), bx, by);
    }

    /**
     * The seed for the next critical point from the shot that reached the previous one: turned by
     * the angle between the two points as seen from the ball, and sped up by the square root of
     * the ratio of their distances (on flat ground the roll grows with the speed squared).
     */
    static Shot nextSeed(Shot reachedPrevious, double ballX, double ballY, double previousX, double previousY,
                         double nextX, double nextY) {
        double previousAngle = Math.atan2(previousY - ballY, previousX - ballX);
        double nextAngle = Math.atan2(nextY - ballY, nextX - ballX);
        double turn = Math.IEEEremainder(nextAngle - previousAngle, 2 * Math.PI);
        double scale = Math.sqrt(Math.hypot(nextX - ballX, nextY - ballY)
                / Math.max(Math.hypot(previousX - ballX, previousY - ballY), 1e-6));
        return Shot.polar(Math.atan2(reachedPrevious.vy(), reachedPrevious.vx()) + turn, reachedPrevious.speed() * scale);
    }
}
