package minigolf.cli;

import java.util.SplittableRandom;

/** Seeded random legal shots: any direction, speed between 10% and 100% of the limit. */
final class RandomShots {
    private final SplittableRandom random;
    private final double maxSpeed;

    RandomShots(long seed, double maxSpeed) {
        this.random = new SplittableRandom(seed);
        this.maxSpeed = maxSpeed;
    }

    /** A moment of the course clock in [0, period) (for courses with moving obstacles). */
    double clock(double period) {
        return random.nextDouble() * period;
    }

    /** The next shot's velocity {vx, vy}. */
    double[] next() {
        double angle = random.nextDouble() * 2 * Math.PI;
        double speed = maxSpeed * (0.1 + 0.9 * random.nextDouble());
        return new double[] {speed * Math.cos(angle), speed * Math.sin(angle)};
    }
}
