package minigolf.bot.path;

import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.Set;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.search.Aim;
import minigolf.bot.search.SearchBot;
import minigolf.bot.search.Target;
import minigolf.physics.ShotResult;

/**
 * {@code graph}: breadth-first search over rest positions. From each node (the ball, then every
 * new cell a shot comes to rest in) it first tries a few aimed shots at the hole, then a fixed fan
 * of shots (directions x speeds); the first node that holes out ends the search, so the plan has
 * the fewest strokes this graph knows. The stroke played is the first shot of that plan.
 */
public final class GraphBot extends SearchBot {
    private final double cellSize;
    private final int directions;
    private final double[] speedFractions;
    private final int maxNodes;
    private final int finishShots;

    /** Defaults: 0.5 m cells, 16 directions x 4 speeds, 40 nodes, 6 aimed shots per node. */
    public GraphBot() {
        this(0.5, 16, new double[] {0.25, 0.5, 0.75, 1.0}, 40, 6);
    }

    public GraphBot(double cellSize, int directions, double[] speedFractions, int maxNodes, int finishShots) {
        this.cellSize = cellSize;
        this.directions = directions;
        this.speedFractions = speedFractions.clone();
        this.maxNodes = maxNodes;
        this.finishShots = finishShots;
    }

    @Override
    public String name() {
        return "graph";
    }

    private record Node(double x, double y, Shot firstShot) {
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        Set<Long> visited = new HashSet<>();
        ArrayDeque<Node> queue = new ArrayDeque<>();
        queue.add(new Node(request.ballX(), request.ballY(), null));
        visited.add(cellKey(request.ballX(), request.ballY()));
        Target rootHole = Target.hole(sim, request.ballX(), request.ballY());
        Node nearest = null;
        double nearestDistance = Double.POSITIVE_INFINITY;
        int expanded = 0;
        while (!queue.isEmpty() && expanded < maxNodes) {
            Node node = queue.poll();
            expanded++;
            sim.phase("graph node " + expanded);
            Target hole = Target.hole(sim, node.x, node.y);
            Aim.Aimed finish = Aim.at(sim, hole, finishShots);
            if (finish != null && finish.reached()) {
                return node.firstShot != null ? node.firstShot : finish.shot();
            }
            double base = hole.angle();
            for (int d = 0; d < directions; d++) {
                double angle = base + 2 * Math.PI * d / directions;
                for (double f : speedFractions) {
                    Shot shot = Shot.polar(angle, f * sim.maxSpeed());
                    ShotResult r = sim.simulate(node.x, node.y, shot);
                    Shot first = node.firstShot != null ? node.firstShot : sim.limit(shot);
                    if (hole.reached(r)) return first;
                    if (r.outcome().isPenalty()) continue;
                    if (visited.add(cellKey(r.endX(), r.endY()))) {
                        queue.add(new Node(r.endX(), r.endY(), first));
                        double distance = Math.hypot(r.endX() - rootHole.x(), r.endY() - rootHole.y());
                        if (distance < nearestDistance) {
                            nearestDistance = distance;
                            nearest = new Node(r.endX(), r.endY(), first);
                        }
                    }
                }
            }
        }
        if (nearest != null) return nearest.firstShot;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(request.world(), request.ballX(), request.ballY());
    }

    private long cellKey(double x, double y) {
        long cx = (long) Math.floor(x / cellSize), cy = (long) Math.floor(y / cellSize);
        return (cx << 32) ^ (cy & 0xffffffffL);
    }
}
