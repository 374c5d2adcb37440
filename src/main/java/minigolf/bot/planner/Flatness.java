package minigolf.bot.planner;

import minigolf.physics.World;

/** Whether a course's ground is flat: no slope anywhere on a fine sample of its playing area. */
final class Flatness {
    /** Samples per side; slopes below {@link #FLAT_SLOPE} count as flat (rounding in expressions). */
    static final int SAMPLES = 64;
    static final double FLAT_SLOPE = 1e-9;

    private Flatness() {
    }

    static boolean isFlat(World world) {
        double[] out = new double[3];
        var b = world.bounds();
        for (int i = 0; i <= SAMPLES; i++) {
            for (int j = 0; j <= SAMPLES; j++) {
                double x = b.minX() + b.width() * i / SAMPLES, y = b.minY() + b.depth() * j / SAMPLES;
                world.terrain().sample(x, y, out);
                if (!(Math.abs(out[1]) <= FLAT_SLOPE && Math.abs(out[2]) <= FLAT_SLOPE)) return false;
            }
        }
        return true;
    }
}
