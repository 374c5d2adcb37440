package minigolf.bot.path;

import java.util.List;
import java.util.SplittableRandom;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.CourseMaps;
import minigolf.bot.SearchBot;
import minigolf.bot.Shot;
import minigolf.bot.search.NewtonSolver;
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
    private final CourseMaps maps = new CourseMaps();

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
        maps.prepare(request.world(), request.token());
        sim.phase("A*");
        double bx = request.ballX(), by = request.ballY();
        Target hole = Target.hole(sim, bx, by);
        List<double[]> points = Waypoints.find(maps.grid(), bx, by, hole.x(), hole.y(), request.token());
        if (points.isEmpty()) points = List.of(new double[] {hole.x(), hole.y()});
        SplittableRandom random = new SplittableRandom(request.seed());
        Shot seed = directGuess(request.world(), bx, by);
        double seedDistance = hole.distance();
        Shot farthest = null;
        for (int k = 0; k < points.size(); k++) {
            double[] p = points.get(k);
            boolean last = k == points.size() - 1;
            Target target = last ? hole : Target.point(bx, by, p[0], p[1], 0.3);
            if (k == 0) {
                seed = Shot.polar(target.angle(), directGuess(request.world(), bx, by).speed()
                        * Math.sqrt(target.distance() / Math.max(seedDistance, 1e-6)));
            } else {
                // The previous solution, turned to the new point and sped up for the longer way.
                double scale = Math.sqrt(target.distance() / Math.max(seedDistance, 1e-6));
                double turn = Math.IEEEremainder(target.angle() - Math.atan2(p[1] - by, p[0] - bx), 2 * Math.PI);
                seed = Shot.polar(Math.atan2(seed.vy(), seed.vx()) + turn, seed.speed() * scale);
            }
            sim.phase((last ? "hole" : "point " + (k + 1)) + " (" + name() + ")");
            Shot solution = solver == Solver.NEWTON
                    ? newton.solve(sim, target, sim.limit(seed), random)
                    : swarm.solve(sim, target, sim.limit(seed), Math.toRadians(15), 0.2, random);
            if (solution == null) break;
            if (last) return solution;
            farthest = solution;
            seed = solution;
            seedDistance = target.distance();
        }
        if (farthest != null) return farthest;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(request.world(), bx, by);
    }
}
