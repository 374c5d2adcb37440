package minigolf.game;

import java.util.ArrayList;
import java.util.List;
import minigolf.collision.CollisionScene;
import minigolf.course.Vec2;
import minigolf.physics.World;

/**
 * Where each player's ball waits at the tee: side by side in a row across the line to the hole,
 * centred on the course's start, so that every ball can be seen and picked. Every spot is checked
 * as the editor checks a start: in play, on dry ground (with a margin the size of a drawn ball),
 * clear of obstacles, away from the cup, no steeper than the tee or what static friction holds,
 * and reached from the tee in a straight line that meets no obstacle, water or edge (so a ball is
 * never put behind a rail). Where a full row does not fit, a narrower one is tried, then a row
 * reaching to one side, then one behind the tee; where nothing fits the balls share the tee, as
 * they did before. A single player starts on the tee itself.
 */
public final class TeeSpots {
    /** Centre to centre, as wide as two drawn balls (three times the real radius) and a gap. */
    public static final double SPACING = 0.16;
    /** The narrowest row tried: the drawn balls then just touch. */
    static final double MIN_SPACING = 0.13;
    /** Dry ground this far round each spot (a drawn ball's radius). */
    static final double DRY_MARGIN = 0.065;

    private TeeSpots() {
    }

    /** The spots of {@code players} balls on {@code world}, seat by seat. */
    public static List<Vec2> of(World world, int players) {
        Vec2 tee = world.course().start();
        if (players <= 1) return List.of(tee);
        Vec2 hole = world.hole().position();
        double ux = hole.x() - tee.x(), uy = hole.y() - tee.y(), len = Math.hypot(ux, uy);
        if (len < 1e-9) {
            ux = 1;
            uy = 0;
        } else {
            ux /= len;
            uy /= len;
        }
        double px = -uy, py = ux; // across the line to the hole
        double teeSlope = slope(world, tee.x(), tee.y());
        for (double spacing = SPACING; spacing >= MIN_SPACING - 1e-9; spacing -= 0.03) {
            // Centred on the tee (seat 0 at the left seen from behind the tee), then reaching to the left
            // or the right of it, then lined up behind it: {direction x, y, first offset, step} in spacings.
            double[][] rows = {
                    {px, py, (players - 1) / 2.0, -1},
                    {px, py, 0, 1}, {px, py, 0, -1},
                    {-ux, -uy, 0, 1}};
            for (double[] row : rows) {
                List<Vec2> spots = new ArrayList<>();
                for (int i = 0; i < players; i++) {
                    double k = (row[2] + row[3] * i) * spacing;
                    spots.add(new Vec2(tee.x() + row[0] * k, tee.y() + row[1] * k));
                }
                if (spots.stream().allMatch(s -> legal(world, tee, s, teeSlope))) return List.copyOf(spots);
            }
        }
        List<Vec2> shared = new ArrayList<>();
        for (int i = 0; i < players; i++) shared.add(tee);
        return shared;
    }

    /** Whether a ball may wait at {@code s}: see the class comment. */
    static boolean legal(World world, Vec2 tee, Vec2 s, double teeSlope) {
        if (!placeable(world, s.x(), s.y(), DRY_MARGIN)) return false;
        double hx = world.hole().position().x(), hy = world.hole().position().y();
        if (Math.hypot(s.x() - hx, s.y() - hy) < world.hole().radius() + 2 * DRY_MARGIN) return false;
        double slopeLimit = Math.max(world.friction().staticFriction(s.x(), s.y()), teeSlope + 0.02);
        if (slope(world, s.x(), s.y()) > slopeLimit) return false;
        // The straight way from the tee: nothing in between (a rail between two lanes, a pond).
        double d = Math.hypot(s.x() - tee.x(), s.y() - tee.y());
        int steps = (int) Math.ceil(d / (0.5 * world.physics().ballRadius()));
        for (int k = 1; k < steps; k++) {
            double t = (double) k / steps;
            double x = tee.x() + t * (s.x() - tee.x()), y = tee.y() + t * (s.y() - tee.y());
            if (!placeable(world, x, y, world.physics().ballRadius())) return false;
        }
        return true;
    }

    /** In play, dry round about, and at least {@code clear} from every obstacle. */
    private static boolean placeable(World world, double x, double y, double clear) {
        double[][] ring = {{0, 0}, {DRY_MARGIN, 0}, {-DRY_MARGIN, 0}, {0, DRY_MARGIN}, {0, -DRY_MARGIN}};
        for (double[] o : ring) {
            double qx = x + o[0], qy = y + o[1];
            if (!world.playArea().contains(qx, qy) || world.terrain().height(qx, qy) < 0) return false;
        }
        CollisionScene scene = world.obstacles();
        double r = world.physics().ballRadius(), h = world.terrain().height(x, y);
        return scene == null || !scene.anyNear(x - clear, y - clear, x + clear, y + clear)
                || scene.clearance(x, y, h + r) >= clear;
    }

    private static double slope(World world, double x, double y) {
        double[] g = new double[3];
        world.terrain().sample(x, y, g);
        return Math.hypot(g[1], g[2]);
    }
}
