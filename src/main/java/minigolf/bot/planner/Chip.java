package minigolf.bot.planner;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;

/**
 * The chip stage (issue 12): where no path along the ground reaches the hole (a green ringed by
 * water, a hole inside low walls, a wall across the course) the planner plays through the air. A
 * fan of directions round the hole's, four launch angles and nine speeds; the first chip that holes
 * wins, else the one resting nearest the hole (along the ground where the distance field reaches,
 * else in a straight line: a chip to the edge of a moat, to chip over it next), refined by a pattern
 * search in direction and speed. A lost ball is never chosen.
 */
final class Chip {
    private static final double[] ELEVATIONS = {Math.toRadians(20), Math.toRadians(35), Math.toRadians(50),
        Math.toRadians(65)};
    /** Speeds as fractions of the course's maxSpeed: a chip carries v^2 sin(2 theta) / g and then rolls. */
    private static final double[] SPEEDS = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    private static final int FAN = 15;
    private static final double FAN_STEP = Math.toRadians(1.5);

    private final Stroke s;
    private Shot best;
    private double bestScore = Double.POSITIVE_INFINITY;

    Chip(Stroke stroke) {
        this.s = stroke;
    }

    /** A chip that holes, or the best resting one, or null when every chip is lost (or chips cannot be played). */
    Shot search() {
        if (s.sim.puttsOnly()) return null;
        double toHole = Math.atan2(s.holeY - s.py, s.holeX - s.px);
        double max = s.world.physics().maxSpeed();
        for (double elevation : ELEVATIONS) {
            for (double fraction : SPEEDS) {
                for (int k = 0; k <= 2 * FAN; k++) {
                    // Straight at the hole first, then alternately either side.
                    int side = (k + 1) / 2 * (k % 2 == 0 ? -1 : 1);
                    if (consider(chip(toHole + side * FAN_STEP, elevation, fraction * max))) return best;
                }
            }
        }
        if (best == null) return null;
        refine();
        return best;
    }

    /** Pattern search round the best chip: direction by 0.5 degrees, speed by 2%, halving three times. */
    private void refine() {
        double angleStep = Math.toRadians(0.5), speedStep = 0.02;
        for (int round = 0; round < 3; round++) {
            boolean moved = true;
            while (moved) {
                moved = false;
                Shot centre = best;
                double h = Math.hypot(centre.vx(), centre.vy());
                double angle = Math.atan2(centre.vy(), centre.vx()), elevation = Math.atan2(centre.vz(), h);
                double speed = centre.speed();
                double[][] moves = {{angleStep, 0}, {-angleStep, 0}, {0, speedStep}, {0, -speedStep}};
                for (double[] m : moves) {
                    double v = speed * (1 + m[1]);
                    if (v > s.world.physics().maxSpeed()) continue;
                    double before = bestScore;
                    if (consider(chip(angle + m[0], elevation, v))) return;
                    if (bestScore < before) moved = true;
                }
            }
            angleStep /= 2;
            speedStep /= 2;
        }
    }

    private static Shot chip(double direction, double elevation, double speed) {
        double horizontal = speed * Math.cos(elevation);
        return new Shot(horizontal * Math.cos(direction), horizontal * Math.sin(direction), speed * Math.sin(elevation));
    }

    /** Simulates a chip; true if it holes (then it is the best). */
    private boolean consider(Shot shot) {
        CountingSimulator sim = s.sim;
        ShotResult r = sim.simulate(s.px, s.py, sim.limit(shot));
        if (r.outcome() == Outcome.HOLED) {
            best = shot;
            bestScore = -1;
            return true;
        }
        if (r.outcome().isPenalty() || r.outcome() == Outcome.TIMEOUT) return false;
        double d = s.field.at(r.endX(), r.endY());
        double score = Double.isFinite(d) ? d : 1e6 + Math.hypot(r.endX() - s.holeX, r.endY() - s.holeY);
        if (score < bestScore) {
            bestScore = score;
            best = shot;
        }
        return false;
    }
}
