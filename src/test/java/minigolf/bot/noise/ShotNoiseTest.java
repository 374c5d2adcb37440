package minigolf.bot.noise;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.map.CourseGrid;
import minigolf.course.CourseException;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The noise's statistics, its determinism and its rules at the edges of play. */
class ShotNoiseTest {
    private static final Path BENCH = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses/bench");
    private static final int N = 4000;

    static World load(String name) {
        try {
            return World.load(BENCH.resolve(name + ".json"));
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** Mean and standard deviation of each column. */
    private static double[][] moments(double[][] samples) {
        int cols = samples[0].length;
        double[][] m = new double[2][cols];
        for (int c = 0; c < cols; c++) {
            double sum = 0, sq = 0;
            for (double[] s : samples) sum += s[c];
            double mean = sum / samples.length;
            for (double[] s : samples) sq += (s[c] - mean) * (s[c] - mean);
            m[0][c] = mean;
            m[1][c] = Math.sqrt(sq / (samples.length - 1));
        }
        return m;
    }

    @Test
    void playedMinusIntendedHasMeanZeroAndTheGivenSpread() {
        World world = load("flat-7m");
        double sp = 0.05, sv = 0.08;
        ShotNoise noise = new ShotNoise(new NoiseModel(sp, sv), world, 12);
        Shot intended = Shot.of(1.2, -0.4);
        double[][] d = new double[N][4];
        for (int i = 0; i < N; i++) {
            PlayedStroke p = noise.play(0, 0, intended);
            d[i] = new double[]{p.x(), p.y(), p.shot().vx() - intended.vx(), p.shot().vy() - intended.vy()};
            assertTrue(p.shot().isPutt(), "a putt stays a putt");
        }
        double[][] m = moments(d);
        double[] sigma = {sp, sp, sv, sv};
        for (int c = 0; c < 4; c++) {
            // Four standard errors: the mean's is sigma/sqrt(N), the standard deviation's about sigma/sqrt(2N).
            assertEquals(0, m[0][c], 4 * sigma[c] / Math.sqrt(N), "mean of column " + c);
            assertEquals(sigma[c], m[1][c], 4 * sigma[c] / Math.sqrt(2.0 * N), "spread of column " + c);
        }
    }

    @Test
    void theSameSeedGivesTheSameStrokes() {
        World world = load("flat-7m");
        NoiseModel model = new NoiseModel(0.02, 0.05);
        ShotNoise a = new ShotNoise(model, world, 7), b = new ShotNoise(model, world, 7), c = new ShotNoise(model, world, 8);
        Shot s = Shot.of(2, 0);
        PlayedStroke first = a.play(0, 0, s);
        assertEquals(first, b.play(0, 0, s));
        assertNotEquals(first, c.play(0, 0, s));
    }

    @Test
    void withoutNoiseTheIntendedStrokeIsPlayed() {
        World world = load("flat-7m");
        ShotNoise none = new ShotNoise(NoiseModel.NONE, world, 1);
        Shot s = new Shot(-0.0, 1.5, 0);
        assertEquals(new PlayedStroke(1, 2, s), none.play(1, 2, s));
    }

    @Test
    void theSpeedLimitHoldsAndTheStartIsNeverInWaterOrOutside() {
        World lake = load("lake-bowl");
        double max = lake.physics().maxSpeed();
        // Huge position noise: most draws are out of bounds or in the lake, so many strokes fall back to the ball.
        ShotNoise noise = new ShotNoise(new NoiseModel(3, 0.5), lake, 5);
        double bx = lake.course().start().x(), by = lake.course().start().y();
        int unmoved = 0;
        for (int i = 0; i < 2000; i++) {
            PlayedStroke p = noise.play(bx, by, Shot.polar(0.3, max));
            assertTrue(p.shot().speed() <= max, "speed " + p.shot().speed());
            assertFalse(CourseGrid.isBlocked(lake, p.x(), p.y()), "start in water or out at " + p.x() + ", " + p.y());
            if (p.x() == bx && p.y() == by) unmoved++;
        }
        assertTrue(unmoved > 0 && unmoved < 2000, "fallbacks to the ball: " + unmoved);
    }

    @Test
    void aChipNeverGoesIntoTheGround() {
        World world = load("flat-7m");
        ShotNoise noise = new ShotNoise(new NoiseModel(0, 0.5), world, 3);
        for (int i = 0; i < 500; i++) assertTrue(noise.play(0, 0, new Shot(1, 0, 0.1)).shot().vz() >= 0);
    }

    @Test
    void negativeOrNonFiniteNoiseIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new NoiseModel(-0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> new NoiseModel(0, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new NoiseModel(Double.POSITIVE_INFINITY, 0));
    }
}
