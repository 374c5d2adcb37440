package minigolf.bot;

/**
 * How far a played stroke strays from the one chosen: independent Gaussian errors with standard
 * deviation {@code position} (metres, per axis) on where the stroke starts and {@code velocity}
 * (m/s, per component) on the velocity played. Known to everyone (it is a game setting), so a bot
 * may plan with it; the draws themselves come from {@link minigolf.bot.noise.ShotNoise}.
 */
public record NoiseModel(double position, double velocity) {
    public static final NoiseModel NONE = new NoiseModel(0, 0);
    /** Larger errors than this are no longer "noise": the course itself would be meaningless. */
    public static final double MAX_SIGMA = 10;

    public NoiseModel {
        check("position", position);
        check("velocity", velocity);
    }

    private static void check(String what, double sigma) {
        if (!(sigma >= 0 && sigma <= MAX_SIGMA)) {
            throw new IllegalArgumentException(what + " noise must be 0 to " + MAX_SIGMA + ", got " + sigma);
        }
    }

    public boolean isNone() {
        return position == 0 && velocity == 0;
    }
}
