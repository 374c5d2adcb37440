package minigolf.online.client;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The benchmark players' pauses before a shot: within think × (1 ± spread), seeded, and exactly think without a spread. */
class ThinkSpreadTest {
    private static HeadlessPlayer player(long thinkMillis) {
        return new HeadlessPlayer(new HeadlessPlayer.Options(URI.create("ws://127.0.0.1:1/"), "flat", 1, List.of(), false, null,
                "P", "straight", null, thinkMillis), line -> { }, line -> { }, null);
    }

    @Test
    void withoutASpreadEveryPauseIsTheThinkTime() {
        HeadlessPlayer p = player(2000);
        for (int i = 0; i < 5; i++) assertEquals(2_000_000_000L, p.thinkNanos());
        p.thinkSpread(0, 7);
        assertEquals(2_000_000_000L, p.thinkNanos());
    }

    @Test
    void pausesSpreadUniformlyAroundTheThinkTimeAndRepeatWithTheSeed() {
        HeadlessPlayer a = player(2000).thinkSpread(0.5, 42), b = player(2000).thinkSpread(0.5, 42);
        HeadlessPlayer c = player(2000).thinkSpread(0.5, 43);
        int n = 20_000, differ = 0;
        double sum = 0, min = Double.MAX_VALUE, max = 0;
        for (int i = 0; i < n; i++) {
            long t = a.thinkNanos();
            assertEquals(t, b.thinkNanos());
            if (t != c.thinkNanos()) differ++;
            sum += t / 1e9;
            min = Math.min(min, t / 1e9);
            max = Math.max(max, t / 1e9);
        }
        // Uniform on [1, 3] s: mean 2 (standard error 0.577/sqrt(n) = 0.004 s), ends near 1 and 3.
        assertEquals(2.0, sum / n, 0.02);
        assertTrue(min >= 1.0 && min < 1.01, "min " + min);
        assertTrue(max <= 3.0 && max > 2.99, "max " + max);
        assertTrue(differ > n * 0.99, "another seed gives other pauses: " + differ);
    }

    @Test
    void aSpreadOutsideZeroToOneIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> player(2000).thinkSpread(1.5, 1));
        assertThrows(IllegalArgumentException.class, () -> player(2000).thinkSpread(-0.1, 1));
        assertThrows(IllegalArgumentException.class, () -> player(2000).thinkSpread(Double.NaN, 1));
    }
}
