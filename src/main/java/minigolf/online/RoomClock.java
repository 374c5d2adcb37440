package minigolf.online;

/**
 * An online room's course clock (where moving obstacles are), as the server keeps it and as each
 * client reckons it: it stands at {@code base} until the moment {@code quietAtMs} (the last ball
 * has stopped rolling) and runs in real time from then on. The server alone decides when a stroke
 * starts: it plays each stroke at its own reading of this clock (plus the shot's wait), never at a
 * client's; a client rebuilds the same function from each event and the moment the event reached
 * it, so every window shows the obstacles moving on the room's clock, behind the server's by the
 * time the message took. Milliseconds are those of one monotonic source per process.
 */
public record RoomClock(double base, long quietAtMs) {
    /** The clock of a hole that starts now (at 0). */
    public static RoomClock startingAt(long nowMs) {
        return new RoomClock(0, nowMs);
    }

    /** The course clock at {@code nowMs} (s). */
    public double at(long nowMs) {
        return base + Math.max(0, nowMs - quietAtMs) / 1000.0;
    }

    /** The moment a stroke whose shot arrives at {@code nowMs} with a wait of {@code waitSeconds} is hit (ms). */
    public long strokeStart(long nowMs, double waitSeconds) {
        return Math.max(nowMs, quietAtMs) + Math.round(waitSeconds * 1000);
    }

    /**
     * The clock after a stroke played from course clock {@code clock} to {@code clockAfter}, hit at
     * {@code startMs}: it stands at {@code clockAfter} while the ball rolls, then runs on; a stroke
     * that ends the hole starts the next hole's clock at 0 when the ball stops.
     */
    public static RoomClock afterStroke(double clock, double clockAfter, long startMs, boolean holeEnded) {
        long quiet = startMs + Math.round(Math.max(0, clockAfter - clock) * 1000);
        return new RoomClock(holeEnded ? 0 : clockAfter, quiet);
    }

    /** The clock after a pick-up at {@code nowMs}: unchanged, or the next hole's from 0 when it ended the hole. */
    public RoomClock afterPickUp(long nowMs, boolean holeEnded) {
        return holeEnded ? startingAt(nowMs) : this;
    }

    /** The clock a client reckons from a room message that says the clock reads {@code clock} and runs again in {@code holdSeconds}. */
    public static RoomClock received(double clock, double holdSeconds, long receivedMs) {
        return new RoomClock(clock, receivedMs + Math.round(Math.max(0, holdSeconds) * 1000));
    }

    /** Seconds until the clock runs again (0 when it runs). */
    public double holdSeconds(long nowMs) {
        return Math.max(0, quietAtMs - nowMs) / 1000.0;
    }
}
