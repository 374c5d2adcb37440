package minigolf.bot.noise;

import java.util.SplittableRandom;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;

/**
 * How a person misplays a chosen putt: the direction off by a Gaussian angle of standard deviation
 * {@code angle} (radians) and the pace off by a Gaussian share {@code pace} of the speed (a player
 * misjudges a long putt by more centimetres per second than a short one, unlike {@link NoiseModel}'s
 * error of fixed size). A chip's lift scales with its pace. Drawn from the caller's stream, so the
 * same seed gives the same played shot.
 */
public record HumanError(double angle, double pace) {
    /** No error: the shot as chosen. */
    public static final HumanError NONE = new HumanError(0, 0);
    /** The slowest pace a draw leaves: a stroke is never played at less than a fifth of its speed. */
    static final double MIN_PACE = 0.2;

    public HumanError {
        if (!(angle >= 0) || !(pace >= 0) || !Double.isFinite(angle) || !Double.isFinite(pace)) {
            throw new IllegalArgumentException("error must be finite and >= 0, got angle " + angle + ", pace " + pace);
        }
    }

    /** This error scaled by {@code factor} (both parts). */
    public HumanError times(double factor) {
        return new HumanError(angle * factor, pace * factor);
    }

    /**
     * The noise model of about the same size for a putt at {@code speed} (the error the noise-aware
     * bot plans for): the larger of the two parts in m/s per velocity component.
     */
    public NoiseModel asNoiseModel(double speed) {
        return new NoiseModel(0, speed * Math.max(angle, pace));
    }

    /** The shot as played: two Gaussian draws from {@code random} on every call (also when the error is none). */
    public Shot play(Shot intended, SplittableRandom random, double maxSpeed) {
        double turn = angle * random.nextGaussian();
        double scale = Math.max(MIN_PACE, 1 + pace * random.nextGaussian());
        if (turn == 0 && scale == 1) return intended;
        double c = Math.cos(turn), s = Math.sin(turn);
        Shot played = new Shot(scale * (c * intended.vx() - s * intended.vy()),
                scale * (s * intended.vx() + c * intended.vy()), scale * intended.vz());
        // A hair below maxSpeed, as CountingSimulator.limit: rounding never trips the engine's check.
        return played.limitedTo(maxSpeed * (1 - 1e-12));
    }
}
