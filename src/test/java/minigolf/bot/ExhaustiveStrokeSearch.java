package minigolf.bot;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;

/**
 * An offline reference for "the fewest strokes possible" (docs/bots.md): breadth first over rest
 * positions, independent of every bot. From each node (the start, then every new cell a shot comes
 * to rest in) a full grid of directions x speeds is simulated; a holed shot from a node of level k
 * ends the search with k + 1 strokes. Shots resting near the hole are refined on a grid ten times
 * finer around them (the success region is far smaller than the coarse step). Penalty shots are
 * never part of a shortest game. Not a proof: a hole the grids step over is not seen, and nodes
 * are merged by cell. Run {@link #main} on course names for the table in docs/bots.md.
 */
final class ExhaustiveStrokeSearch {
    /** The search's resolution. */
    record Grid(double cell, int directions, int speeds, int maxLevels, double nearHole, int refinements) {
        static final Grid DEFAULT = new Grid(0.3, 180, 24, 8, 0.6, 5);
    }

    /** One node: where the ball rests, how it got there (the previous node and its shot). */
    private record Node(double x, double y, Node parent, double vx, double vy) {
    }

    /** The result: fewest strokes found (0 = none within maxLevels), the shots, and the effort. */
    record Result(int strokes, List<double[]> shots, List<Integer> nodesPerLevel, long simulations, double seconds) {
    }

    private ExhaustiveStrokeSearch() {
    }

    static Result search(World world, Grid grid) {
        return search(world, grid, false);
    }

    static Result search(World world, Grid grid, boolean progress) {
        long t0 = System.nanoTime();
        Simulator engine = new Simulator(world, SimulationSettings.DEFAULT);
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        double vMax = world.physics().maxSpeed();
        double dAngle = 2 * Math.PI / grid.directions(), dSpeed = vMax / grid.speeds();
        Set<Long> visited = new HashSet<>();
        List<Node> level = List.of(new Node(world.course().start().x(), world.course().start().y(), null, 0, 0));
        visited.add(key(level.get(0).x, level.get(0).y, grid.cell()));
        List<Integer> counts = new ArrayList<>();
        long sims = 0;
        for (int k = 0; k < grid.maxLevels() && !level.isEmpty(); k++) {
            counts.add(level.size());
            if (progress) System.err.printf(Locale.ROOT, "  level %d: %d nodes, %d simulations so far, %.0f s%n", k, level.size(), sims, (System.nanoTime() - t0) / 1e9);
            List<Node> next = new ArrayList<>();
            for (Node node : level) {
                double base = Math.atan2(hy - node.y, hx - node.x);
                List<double[]> near = new ArrayList<>();
                for (int d = 0; d < grid.directions(); d++) {
                    double angle = base + d * dAngle;
                    for (int s = 1; s <= grid.speeds(); s++) {
                        double speed = s * dSpeed;
                        double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
                        ShotResult r = engine.simulate(node.x, node.y, vx, vy);
                        sims++;
                        if (r.outcome() == Outcome.HOLED) return done(new Node(hx, hy, node, vx, vy), counts, sims, t0);
                        if (r.outcome() != Outcome.STOPPED) continue;
                        double miss = Math.hypot(r.endX() - hx, r.endY() - hy);
                        if (miss < grid.nearHole()) near.add(new double[] {miss, angle, speed});
                        if (visited.add(key(r.endX(), r.endY(), grid.cell()))) {
                            next.add(new Node(r.endX(), r.endY(), node, vx, vy));
                        }
                    }
                }
                near.sort((a, b) -> Double.compare(a[0], b[0]));
                for (int i = 0; i < Math.min(grid.refinements(), near.size()); i++) {
                    double[] c = near.get(i);
                    for (int a = -10; a <= 10; a++) {
                        for (int s = -5; s <= 5; s++) {
                            double angle = c[1] + a * dAngle / 10, speed = Math.min(c[2] + s * dSpeed / 5, vMax);
                            double vx = speed * Math.cos(angle), vy = speed * Math.sin(angle);
                            sims++;
                            if (engine.simulate(node.x, node.y, vx, vy).outcome() == Outcome.HOLED) {
                                return done(new Node(hx, hy, node, vx, vy), counts, sims, t0);
                            }
                        }
                    }
                }
            }
            level = next;
        }
        return new Result(0, List.of(), counts, sims, (System.nanoTime() - t0) / 1e9);
    }

    private static Result done(Node holed, List<Integer> counts, long sims, long t0) {
        List<double[]> shots = new ArrayList<>();
        for (Node n = holed; n.parent != null; n = n.parent) {
            shots.add(0, new double[] {n.parent.x, n.parent.y, n.vx, n.vy});
        }
        return new Result(shots.size(), shots, counts, sims, (System.nanoTime() - t0) / 1e9);
    }

    private static long key(double x, double y, double cell) {
        long cx = (long) Math.floor(x / cell), cy = (long) Math.floor(y / cell);
        return (cx << 32) ^ (cy & 0xffffffffL);
    }

    /** Prints one line per course: fewest strokes found, nodes per level, simulations, seconds, the shots. */
    public static void main(String[] args) {
        for (String arg : args) {
            // NAME or NAME:LEVELS (search at most LEVELS strokes deep)
            String name = arg.contains(":") ? arg.substring(0, arg.indexOf(':')) : arg;
            Grid d = Grid.DEFAULT;
            Grid grid = arg.contains(":") ? new Grid(d.cell(), d.directions(), d.speeds(),
                    Integer.parseInt(arg.substring(arg.indexOf(':') + 1)), d.nearHole(), d.refinements()) : d;
            Result r = search(BenchCourses.load(name), grid, true);
            StringBuilder shots = new StringBuilder();
            for (double[] s : r.shots()) {
                shots.append(String.format(Locale.ROOT, " (%.3f,%.3f)->v(%.4f,%.4f)", s[0], s[1], s[2], s[3]));
            }
            System.out.printf(Locale.ROOT, "%s fewest %s nodes %s sims %d %.1f s%s%n", name,
                    r.strokes() == 0 ? ">" + grid.maxLevels() : Integer.toString(r.strokes()),
                    r.nodesPerLevel(), r.simulations(), r.seconds(), shots);
            System.out.flush();
        }
    }
}
