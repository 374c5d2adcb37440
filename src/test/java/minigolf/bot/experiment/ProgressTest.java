package minigolf.bot.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

/** The bar on a terminal, the periodic lines in a batch job, and the closing line of both. */
class ProgressTest {
    @Test
    void aTerminalGetsABarRedrawnInPlace() {
        StringWriter text = new StringWriter();
        try (Progress p = new Progress(new PrintWriter(text), true, 2, 0, 60)) {
            p.finished();
            p.finished();
        }
        String out = text.toString();
        assertTrue(out.startsWith("\r[###############               ] 1/2 runs (50%), "), out);
        assertTrue(out.contains("\r[##############################] 2/2 runs (100%), "), out);
        assertTrue(out.contains("\nexperiment: 2/2 runs done (2 now, 0 resumed) in "), out);
    }

    @Test
    void aBatchJobGetsALineEveryIntervalAndNoBar() throws InterruptedException {
        StringWriter text = new StringWriter();
        try (Progress p = new Progress(new PrintWriter(text), false, 10, 2, 1)) {
            for (int i = 0; i < 3; i++) p.finished();
            // The ticker's first line comes after one interval; wait for it without timing anything.
            for (int i = 0; i < 1000 && !text.toString().contains("\n"); i++) Thread.sleep(10);
        }
        String out = text.toString();
        assertFalse(out.contains("\r") || out.contains("[#"), out);
        String first = out.lines().findFirst().orElseThrow();
        assertTrue(first.matches("experiment: 5/10 runs \\(50%\\), [0-9.]+ runs/s, about [0-9]+ (s|min) left"), first);
        assertTrue(out.lines().reduce((a, b) -> b).orElseThrow().startsWith("experiment: 5/10 runs done (3 now, 2 resumed) in "), out);
    }

    @Test
    void durationsReadNaturally() {
        assertEquals("42 s", Progress.duration(42.4));
        assertEquals("7 min", Progress.duration(420));
        assertEquals("3 h 20 min", Progress.duration(12_000));
    }
}
