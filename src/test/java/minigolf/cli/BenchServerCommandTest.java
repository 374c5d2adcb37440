package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import org.junit.jupiter.api.Test;

/** bench-server in small: a real server process, two rooms of two bot players, every stroke checked against the database. */
class BenchServerCommandTest {
    @Test
    void twoRoomsPlayToTheEndWithEveryStrokeStoredOnce() throws Exception {
        CliRun r = CliRun.of("bench-server", "--rooms", "2", "--seats", "2", "--course", "flat", "--think", "0",
                "--timeout", "300");
        assertEquals(0, r.code(), r.err() + r.out());
        JsonNode j = r.json();
        assertEquals(4, j.get("players").asInt());
        assertEquals(2, j.get("roomsFinished").asInt());
        assertEquals(0, j.get("lostOrDuplicated").asInt());
        // Every stroke a client timed is one the server stored, and each of the four players played at least one.
        assertEquals(j.get("shots").asLong(), j.get("storedStrokes").asLong());
        assertTrue(j.get("shots").asLong() >= 4, r.out());
        assertTrue(j.get("p50Ms").asDouble() > 0 && j.get("p50Ms").asDouble() <= j.get("p99Ms").asDouble()
                && j.get("p99Ms").asDouble() <= j.get("maxMs").asDouble(), r.out());
        assertTrue(j.get("serverPeakRssMb").asInt() > 0, r.out());
        assertFalse(j.has("failures"), r.out());
        assertEquals(0.5, j.get("thinkSpread").asDouble(), r.out());
        assertEquals(1, j.get("seed").asLong(), r.out());
    }

    @Test
    void badOptionsAreRefusedInOneLine() {
        for (String[] bad : new String[][]{{"--seats", "5"}, {"--rooms", "0"}, {"--think", "-1"}, {"--think-spread", "1.5"}, {"--server-heap", "lots"}}) {
            String[] args = {"bench-server", bad[0], bad[1]};
            CliRun r = CliRun.of(args);
            assertEquals(2, r.code(), String.join(" ", args) + ": " + r.err());
            String err = r.err().strip();
            assertFalse(err.contains("\n") || err.contains("Exception"), err);
            assertTrue(err.contains(bad[0]), err);
        }
    }
}
