package minigolf.bot.path;

import static org.junit.jupiter.api.Assertions.assertEquals;

import minigolf.bot.Shot;
import org.junit.jupiter.api.Test;

/** The guided bots' seed for the next critical point. */
class GuidedBotTest {
    @Test
    void theNextSeedTurnsTowardsTheNextPoint() {
        // The shot that reached (2, 0) from the origin went east at 2 m/s; the next point (0, 8) is
        // due north and 4 times as far: the seed turns 90 degrees left and speeds up by sqrt(4) = 2.
        Shot seed = GuidedBot.nextSeed(Shot.of(2, 0), 0, 0, 2, 0, 0, 8);
        assertEquals(0, seed.vx(), 1e-12);
        assertEquals(4, seed.vy(), 1e-12);
    }

    @Test
    void theTurnIsRelativeToTheShotNotAbsolute() {
        // The shot that reached the first point left 10 degrees right of it (a slope bent it back):
        // the seed keeps that correction and turns by the points' angle, 45 degrees, from there.
        Shot reached = Shot.polar(Math.toRadians(-10), 3);
        Shot seed = GuidedBot.nextSeed(reached, 1, 1, 4, 1, 4, 4);
        assertEquals(35, Math.toDegrees(Math.atan2(seed.vy(), seed.vx())), 1e-9);
        assertEquals(3 * Math.sqrt(Math.sqrt(18) / 3), seed.speed(), 1e-12);
    }

    @Test
    void turningTheWrongWayRoundIsTheShortWay() {
        // From 170 degrees to -170 degrees is 20 degrees left, not 340 right.
        Shot seed = GuidedBot.nextSeed(Shot.polar(Math.toRadians(170), 1), 0, 0,
                Math.cos(Math.toRadians(170)), Math.sin(Math.toRadians(170)),
                Math.cos(Math.toRadians(-170)), Math.sin(Math.toRadians(-170)));
        assertEquals(-170, Math.toDegrees(Math.atan2(seed.vy(), seed.vx())), 1e-9);
    }
}
