package minigolf.online;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The room's course clock: stands while a ball rolls, runs in real time after; a new hole starts at 0. */
class RoomClockTest {
    @Test
    void itRunsFromTheStartOfTheHole() {
        RoomClock c = RoomClock.startingAt(10_000);
        assertEquals(0, c.at(9_000), 0, "not before the start");
        assertEquals(2.5, c.at(12_500), 1e-12);
        // A shot that arrives at 12.5 s with a wait of 0.75 s is hit 0.75 s later, at clock 3.25.
        assertEquals(13_250, c.strokeStart(12_500, 0.75));
        assertEquals(3.25, c.at(c.strokeStart(12_500, 0.75)), 1e-12);
    }

    @Test
    void itStandsWhileTheBallRollsThenRunsOn() {
        // Hit at clock 3.25 (at 13.25 s), the ball rolls 4 s: the clock stands at 7.25 until 17.25 s.
        RoomClock c = RoomClock.afterStroke(3.25, 7.25, 13_250, false);
        assertEquals(7.25, c.at(15_000), 0);
        assertEquals(7.25, c.at(17_250), 0);
        assertEquals(8.25, c.at(18_250), 1e-12);
        assertEquals(0.5, c.holdSeconds(16_750), 1e-12);
        assertEquals(0, c.holdSeconds(20_000), 0);
        // A shot that arrives while the ball still rolls (a bot that did not wait) is hit when it stops.
        assertEquals(17_250, c.strokeStart(16_000, 0));
        assertEquals(7.25, c.at(c.strokeStart(16_000, 0)), 0);
    }

    @Test
    void aStrokeThatEndsTheHoleStartsTheNextHolesClockWhenTheBallStops() {
        RoomClock c = RoomClock.afterStroke(3.25, 7.25, 13_250, true);
        assertEquals(0, c.at(17_000), 0);
        assertEquals(1.5, c.at(18_750), 1e-12);
        assertEquals(c, c.afterPickUp(20_000, false), "a pick-up that leaves the hole open changes nothing");
        assertEquals(0.25, c.afterPickUp(20_000, true).at(20_250), 1e-12);
    }

    @Test
    void aClientRunsOnFromWhatARoomMessageSays() {
        // "clock": 4.0, "clockRunsIn": 0.3, arriving at 1,000 ms of the client's own clock.
        RoomClock c = RoomClock.received(4.0, 0.3, 1_000);
        assertEquals(4.0, c.at(1_200), 0);
        assertEquals(4.4, c.at(1_700), 1e-12, "runs from 1,300 ms on");
    }
}
