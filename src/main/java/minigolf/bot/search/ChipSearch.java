package minigolf.bot.search;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseGrid;
import minigolf.bot.map.DistanceField;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.World;

/**
 * A search through the air, for a ball from which no path along the ground reaches the hole (a
 * green ringed by water, a hole inside low walls, a wall across the course). A fan of directions
 * round the hole's, five launch angles (up to a lob of 78 degrees, for a ball lying against the wall
 * it must clear) and nine speeds; the first chip that holes wins, else the one resting nearest the hole (along the ground where the distance field reaches, else in a
 * straight line, with room for the next lob: a chip to near the edge of a moat, to chip over it next), refined by a pattern search
 * in direction and speed. A lost ball is never chosen, nor one that rests within 5 cm of where it
 * started. Shared by the planner's chip stage and, as
 * their way out when cut off, by every other search bot ({@link SearchBot}).
 */
public final class ChipSearch {
    private static final double[] ELEVATIONS = {Math.toRadians(20), Math.toRadians(35), Math.toRadians(50),
        Math.toRadians(65), Math.toRadians(78)};
    /** A chip that rests this close to where it started (m) gets nowhere: never chosen (a ball leaning on a wall). */
    private static final double NO_PROGRESS = 0.05;
    /**
     * Room a lob needs (m from water, walls or the edge): a ball resting against the wall it must
     * clear cannot chip over it (it hits the wall's face before it rises), so still cut off it
     * prefers to rest this far from everything, nearest the hole among those.
     */
    private static final double LOB_ROOM = 0.3;
    /** Speeds as fractions of the course's maxSpeed: a chip carries v^2 sin(2 theta) / g and then rolls. */
    private static final double[] SPEEDS = {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    private static final int FAN = 15;
    private static final double FAN_STEP = Math.toRadians(1.5);

    private final CountingSimulator sim;
    private final World world;
    private final DistanceField field;
    private final CourseGrid grid;
    private final double px, py, holeX, holeY;
    private Shot best;
    private double bestScore = Double.POSITIVE_INFINITY;

    /**
     * @param grid the course's grid (for the room round a resting ball)
     * @param field the distance along the ground to the hole (infinite where cut off)
     * @param px the ball
     * @param py the ball
     */
    public ChipSearch(CountingSimulator sim, CourseGrid grid, DistanceField field, double px, double py) {
        this.sim = sim;
        this.world = sim.world();
        this.grid = grid;
        this.field = field;
        this.px = px;
        this.py = py;
        this.holeX = world.hole().position().x();
        this.holeY = world.hole().position().y();
    }

    /** Whether no path along the ground leads from the ball to the hole. */
    public static boolean cutOff(DistanceField field, double x, double y) {
        return !Double.isFinite(field.at(x, y));
    }

    /** A chip that holes, or the best resting one, or null when every chip is lost (or chips cannot be played). */
    public Shot search() {
        if (sim.puttsOnly()) return null;
        double toHole = Math.atan2(holeY - py, holeX - px);
        double max = world.physics().maxSpeed();
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
                    if (v > world.physics().maxSpeed()) continue;
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
        ShotResult r = sim.simulate(px, py, sim.limit(shot));
        if (r.outcome() == Outcome.HOLED) {
            best = shot;
            bestScore = -1;
            return true;
        }
        if (r.outcome().isPenalty() || r.outcome() == Outcome.TIMEOUT) return false;
        if (Math.hypot(r.endX() - px, r.endY() - py) < NO_PROGRESS) return false;
        double d = field.at(r.endX(), r.endY());
        double score = Double.isFinite(d) ? d : 1e6 + Math.hypot(r.endX() - holeX, r.endY() - holeY)
                + (grid.clearance(r.endX(), r.endY()) < LOB_ROOM ? 1e3 : 0);
        if (score < bestScore) {
            bestScore = score;
            best = shot;
        }
        return false;
    }
}
