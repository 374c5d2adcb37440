package minigolf.game;

import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Stroke;
import minigolf.physics.World;

import java.util.Arrays;

/**
 * The aim guide for beginners ({@link UserSettings#aimGuide()}): where the ball aimed now would go,
 * from the real engine ({@link Stroke}, the game's own integrator and step): in the game the whole
 * putt until it stops, drops or leaves play, capped at {@link #FULL_SECONDS} of motion (worked out
 * off the render thread, {@link AimGuideWorker}); any shorter window on request. {@code points} are
 * (x, y, z) triplets of the ball's contact point, one per frame of dt as the game shows it, from the
 * ball's position on; {@code outcome} is how the
 * stroke ends if it ends within the window (holed, stopped, water, out), else null.
 */
public record AimGuide(float[] points, Outcome outcome) {
    /** A one-second window (the guide before it showed the whole putt; tests compare with the played stroke). */
    public static final double SECONDS = 1.0;
    /**
     * The game's guide: the whole stroke, up to this many seconds of the ball's motion (a putt on
     * the bundled courses ends within about 10 s; the cap keeps a ball circling a cone from
     * costing more than about 2,000 steps).
     */
    public static final double FULL_SECONDS = 30.0;

    public int pointCount() {
        return points.length / 3;
    }

    /** The guide for a putt (vx, vy) from (x, y), simulated for {@code seconds} with the game's settings. */
    public static AimGuide preview(World world, SimulationSettings settings, double x, double y, double vx, double vy,
                                   double seconds) {
        return preview(world, settings, x, y, vx, vy, 0, seconds);
    }

    /** The guide for a putt or a chip (vz &gt; 0: its flight, then its roll), as the engine plays it. */
    public static AimGuide preview(World world, SimulationSettings settings, double x, double y, double vx, double vy,
                                   double vz, double seconds) {
        return preview(world, settings, x, y, vx, vy, vz, 0, seconds);
    }

    /**
     * The guide for a stroke hit at course clock {@code clock} (s): where obstacles move, the
     * moment the stroke will start, so the guide shows what the player will get.
     */
    public static AimGuide preview(World world, SimulationSettings settings, double x, double y, double vx, double vy,
                                   double vz, double clock, double seconds) {
        if (!(seconds > 0)) throw new IllegalArgumentException("seconds must be > 0, got " + seconds);
        SimulationSettings cut = new SimulationSettings(settings.integrator(), settings.dt(), Math.min(seconds, settings.maxTime()));
        float[][] buffer = {new float[3 * 64]};
        int[] n = {0};
        add(buffer, n, x, y, world.terrain().height(x, y));
        // Frame by frame, as the game shows the ball: the steps themselves may be longer than a frame.
        Stroke stroke = new Stroke(world, cut, x, y, vx, vy, vz, clock, null, false);
        while (!stroke.isFinished()) {
            stroke.step();
            add(buffer, n, stroke.x(), stroke.y(), stroke.z());
        }
        Outcome outcome = stroke.result().outcome() == Outcome.TIMEOUT ? null : stroke.result().outcome();
        return new AimGuide(Arrays.copyOf(buffer[0], 3 * n[0]), outcome);
    }

    private static void add(float[][] buffer, int[] n, double x, double y, double z) {
        if (3 * n[0] + 3 > buffer[0].length) buffer[0] = Arrays.copyOf(buffer[0], buffer[0].length * 2);
        float[] b = buffer[0];
        b[3 * n[0]] = (float) x;
        b[3 * n[0] + 1] = (float) y;
        b[3 * n[0] + 2] = (float) z;
        n[0]++;
    }
}
