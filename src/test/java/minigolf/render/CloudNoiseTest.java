package minigolf.render;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The baked cloud tile: periodic, in range, deterministic, and noisy enough to show clouds. */
class CloudNoiseTest {
    @Test
    void latticeValuesRepeatEveryPeriod() {
        for (int p : new int[]{16, 32, 128}) {
            for (int i = -40; i < 40; i += 3) {
                for (int j = -40; j < 40; j += 7) {
                    double v = minigolf.texture.Noise.lattice(i, j, p);
                    assertEquals(v, minigolf.texture.Noise.lattice(i + p, j, p));
                    assertEquals(v, minigolf.texture.Noise.lattice(i, j - p, p));
                    assertTrue(v >= 0 && v < 1, "lattice value " + v);
                }
            }
        }
    }

    @Test
    void theTileHasNoSeam() {
        // fbm at u = 0 and u = 1 (and v) are the same point of the periodic pattern.
        for (double t = 0; t < 1; t += 0.037) {
            assertEquals(CloudNoise.fbm(0, t), CloudNoise.fbm(1, t), 1e-12);
            assertEquals(CloudNoise.fbm(t, 0), CloudNoise.fbm(t, 1), 1e-12);
        }
    }

    @Test
    void noiseInterpolatesTheLatticeAndStaysInRange() {
        // At lattice points the noise is the lattice value; between them it stays within their range.
        assertEquals(minigolf.texture.Noise.lattice(3, 5, 16), CloudNoise.noise(3, 5, 16), 1e-15);
        double a = minigolf.texture.Noise.lattice(3, 5, 16), b = minigolf.texture.Noise.lattice(4, 5, 16);
        double mid = CloudNoise.noise(3.5, 5, 16);
        assertEquals((a + b) / 2, mid, 1e-12); // the smoothstep weight is exactly 1/2 half way
        double min = 1, max = 0, sum = 0;
        int n = 0;
        for (double u = 0; u < 1; u += 0.01) {
            for (double v = 0; v < 1; v += 0.01) {
                double f = CloudNoise.fbm(u, v);
                min = Math.min(min, f);
                max = Math.max(max, f);
                sum += f;
                n++;
            }
        }
        assertTrue(min >= 0 && max < 1, "fbm out of [0, 1): " + min + " .. " + max);
        // Enough contrast that the sky's cover threshold (0.53 to 0.83) leaves both clear sky and cloud.
        assertTrue(min < 0.35 && max > 0.7, "too little contrast: " + min + " .. " + max);
        assertEquals(0.5, sum / n, 0.08);
    }

    @Test
    void pixelsAreDeterministicAndSized() {
        byte[] a = CloudNoise.rgba(128), b = CloudNoise.rgba(128);
        assertArrayEquals(a, b);
        assertEquals(128 * 128 * 4, a.length);
        assertEquals((byte) 255, a[2]);
        assertEquals((byte) 255, a[3]);
        assertEquals(Math.round(CloudNoise.fbm(0, 0) * 255), a[0] & 0xFF);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CloudNoise.rgba(100));
        assertTrue(e.getMessage().contains("multiple of 128"), e.getMessage());
    }
}
