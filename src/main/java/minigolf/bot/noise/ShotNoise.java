package minigolf.bot.noise;

import java.util.SplittableRandom;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseGrid;
import minigolf.physics.World;

/**
 * Draws the played stroke from the intended one under a {@link NoiseModel}, from its own seeded
 * stream: the same seed and the same intended strokes give the same played strokes.
 *
 * <p>Rules (docs/bots.md, "Noise"):
 * <ul>
 * <li>Start: the ball is moved by N(0, σp) per axis. A start in water, out of play or inside an
 *     obstacle ({@link CourseGrid#isBlocked}) is drawn again, up to {@link #START_TRIES} times;
 *     then the stroke starts where the ball lies (no position error), so noise never puts a ball
 *     where the rules say it cannot be.</li>
 * <li>Velocity: N(0, σv) on vx and vy; a chip's vz too, but never below 0 (a ball cannot be
 *     struck into the ground: it becomes a putt). A played speed above the course's maximum is
 *     scaled down to it (same direction), as the game does with every shot.</li>
 * </ul>
 * Every stroke draws the same count of numbers for the velocity, whatever the start needed, so a
 * seed's velocity errors do not depend on the position noise's retries.
 */
public final class ShotNoise {
    /** Draws of a blocked start before giving up on the position error for this stroke. */
    public static final int START_TRIES = 8;

    private final NoiseModel model;
    private final World world;
    private final SplittableRandom positions;
    private final SplittableRandom velocities;

    public ShotNoise(NoiseModel model, World world, long seed) {
        this.model = model;
        this.world = world;
        SplittableRandom root = new SplittableRandom(seed);
        this.positions = root.split();
        this.velocities = root.split();
    }

    public NoiseModel model() {
        return model;
    }

    /** The stroke as played when the ball lies at (x, y) and the player chose {@code intended}. */
    public PlayedStroke play(double x, double y, Shot intended) {
        return play(model, world, x, y, intended, positions, velocities);
    }

    /** One draw with the caller's streams (a bot sampling the model for itself). */
    public static PlayedStroke play(NoiseModel model, World world, double x, double y, Shot intended,
                                    SplittableRandom positions, SplittableRandom velocities) {
        double sx = x, sy = y;
        if (model.position() > 0) {
            for (int i = 0; i < START_TRIES; i++) {
                double px = x + model.position() * positions.nextGaussian();
                double py = y + model.position() * positions.nextGaussian();
                if (!CourseGrid.isBlocked(world, px, py)) {
                    sx = px;
                    sy = py;
                    break;
                }
            }
        }
        double s = model.velocity();
        double ex = velocities.nextGaussian(), ey = velocities.nextGaussian(), ez = velocities.nextGaussian();
        // Without velocity noise the intended shot itself (adding 0 could turn -0.0 into 0.0).
        Shot played = s == 0 ? intended : new Shot(intended.vx() + s * ex, intended.vy() + s * ey,
                intended.isPutt() ? 0 : Math.max(0, intended.vz() + s * ez));
        // A hair below maxSpeed, as CountingSimulator.limit: rounding never trips the engine's check.
        return new PlayedStroke(sx, sy, played.limitedTo(world.physics().maxSpeed() * (1 - 1e-12)));
    }
}
