package minigolf.physics;

import minigolf.collision.CollisionScene;
import minigolf.collision.Gates;
import minigolf.collision.Hit;
import minigolf.collision.MovingObstacles;

/**
 * Everything solid a stroke's ball can hit: the still obstacles ({@link CollisionScene}), the
 * one-way gates ({@link Gates}) and the moving obstacles ({@link MovingObstacles}, swept over the
 * chord's times on the course clock). One per stroke (it holds the moving obstacles' buffers).
 */
final class Solids {
    /** The still obstacles, the gates, the moving ones; each null when the course has none. */
    private final CollisionScene scene;
    private final Gates gates;
    private final MovingObstacles moving;
    private final MovingObstacles.Sweeper sweeper;
    /** The breakable bricks (null when the course has none) and what is left of them this stroke. */
    private final CollisionScene bricks;
    final BrickHits brickHits;
    private final Hit other = new Hit();
    private final double[] scratch = new double[3];

    private Solids(CollisionScene scene, Gates gates, MovingObstacles moving, CollisionScene bricks, int brickCount) {
        this.scene = scene;
        this.bricks = bricks;
        this.brickHits = bricks == null ? null : new BrickHits(brickCount);
        this.gates = gates;
        this.moving = moving;
        this.sweeper = moving == null ? null : moving.sweeper();
    }

    /** The world's solids, or null when it has none. */
    static Solids of(World world) {
        if (world.obstacles() == null && world.gates() == null && world.moving() == null && world.bricks() == null) {
            return null;
        }
        return new Solids(world.obstacles(), world.gates(), world.moving(), world.bricks(), world.course().bricks().size());
    }

    /** Whether anything still (an obstacle or a gate) is listed near the rectangle of centre positions. */
    boolean anyStillNear(double minX, double minY, double maxX, double maxY) {
        return (scene != null && scene.anyNear(minX, minY, maxX, maxY))
                || (bricks != null && bricks.anyNear(minX, minY, maxX, maxY))
                || (gates != null && gates.anyNear(minX, minY, maxX, maxY));
    }

    /** Whether anything, still or moving, may come within reach of the rectangle of centre positions. */
    boolean anyNear(double minX, double minY, double maxX, double maxY) {
        return anyStillNear(minX, minY, maxX, maxY) || (moving != null && moving.anyNear(minX, minY, maxX, maxY));
    }

    /** Whether a moving obstacle may come within reach of the rectangle of centre positions. */
    boolean anyMovingNear(double minX, double minY, double maxX, double maxY) {
        return moving != null && moving.anyNear(minX, minY, maxX, maxY);
    }

    /** As {@link CollisionScene#anyShapeNear}, with gates and moving obstacles. */
    boolean anyShapeNear(double minX, double minY, double maxX, double maxY) {
        return (scene != null && scene.anyShapeNear(minX, minY, maxX, maxY))
                || (bricks != null && bricks.anyShapeNear(minX, minY, maxX, maxY))
                || (gates != null && gates.anyNear(minX, minY, maxX, maxY))
                || (moving != null && moving.anyNear(minX, minY, maxX, maxY));
    }

    /**
     * Whether anything may come within {@code margin} of the segment from (x0, y0) to (x1, y1): still
     * shapes by their outlines ({@link CollisionScene#anyShapeNearPath}), gates and moving obstacles
     * by the segment's rectangle.
     */
    boolean anyShapeNearPath(double x0, double y0, double x1, double y1, double margin) {
        double minX = Math.min(x0, x1) - margin, maxX = Math.max(x0, x1) + margin;
        double minY = Math.min(y0, y1) - margin, maxY = Math.max(y0, y1) + margin;
        return (gates != null && gates.anyNear(minX, minY, maxX, maxY))
                || (moving != null && moving.anyNear(minX, minY, maxX, maxY))
                || (scene != null && scene.anyShapeNearPath(x0, y0, x1, y1, margin))
                || (bricks != null && bricks.anyShapeNearPath(x0, y0, x1, y1, margin));
    }

    /**
     * Sweeps the ball's centre from p0 (course clock t0) to p1 (t1) against everything; the first
     * contact in {@code hit}. A still contact's fraction is the sweep's exact one; a moving
     * obstacle's is already backed off by {@code skin} in its frame ({@link Hit#moving} set).
     */
    boolean sweep(double x0, double y0, double z0, double t0, double x1, double y1, double z1, double t1, double skin,
                  Hit hit) {
        boolean found = sweepStill(x0, y0, z0, x1, y1, z1, hit);
        if (moving != null) {
            double f = sweeper.sweep(x0, y0, z0, t0, x1, y1, z1, t1, found ? hit.fraction : 1.0 + 1e-12, skin, other);
            if (f < (found ? hit.fraction : Double.POSITIVE_INFINITY)) {
                hit.set(other);
                found = f <= 1;
            }
        }
        return found;
    }

    /** The sweep from p0 to p1 against the still obstacles and the gates only. */
    boolean sweepStill(double x0, double y0, double z0, double x1, double y1, double z1, Hit hit) {
        double best = Double.POSITIVE_INFINITY;
        if (scene != null && scene.sweep(x0, y0, z0, x1, y1, z1, hit, scratch)) best = hit.fraction;
        if (bricks != null && bricks.sweep(x0, y0, z0, x1, y1, z1, other, scratch, brickHits.gone)
                && other.fraction < best) {
            best = other.fraction;
            hit.set(other);
            hit.brick = other.obstacle;
        }
        if (gates != null) {
            double f = gates.sweep(x0, y0, z0, x1, y1, z1, Math.min(best, 1.0 + 1e-12), other, scratch);
            if (f < best) {
                best = f;
                hit.set(other);
            }
        }
        return best <= 1;
    }

    /**
     * The first moment (course clock) a moving obstacle touches a ball resting with its centre at
     * (x, y, z) from {@code clock} on, with {@code hit} filled; +infinity if none ever does.
     */
    double stillContact(double x, double y, double z, double clock, Hit hit) {
        return sweeper == null ? Double.POSITIVE_INFINITY : sweeper.stillContact(x, y, z, clock, hit);
    }

    boolean hasMoving() {
        return moving != null;
    }
}
