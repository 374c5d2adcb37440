package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import minigolf.physics.Outcome;
import org.junit.jupiter.api.Test;

/** What a player reads after a stroke: plain words, the score's name against par, no coordinates. */
class StrokeNewsTest {
    private static ShotRecord shot(Outcome o, double endX, double endY) {
        return new ShotRecord(0, -3, 0, 2, 0, o, endX, endY);
    }

    @Test
    void outcomesInAPlayersWords() {
        PlayerState rolling = new PlayerState(1.2, 0.3, 2, 0, PlayerStatus.PLAYING);
        assertEquals("In the water: +1 stroke", StrokeNews.of(shot(Outcome.WATER, -0.9, 0.1),
                new PlayerState(-3, 0, 1, 1, PlayerStatus.PLAYING), "Ann", false, 3, 3, 0.5));
        assertEquals("Ann is out of bounds: +1 stroke", StrokeNews.of(shot(Outcome.OUT, -4, 0),
                new PlayerState(-3, 0, 1, 1, PlayerStatus.PLAYING), "Ann", true, 3, 3, 0.5));
        assertEquals("Holed in 3 \u2014 birdie!", StrokeNews.of(shot(Outcome.HOLED, 3, 0.5),
                new PlayerState(3, 0.5, 3, 0, PlayerStatus.HOLED), "Ann", false, 4, 3, 0.5));
        assertEquals("Bob holed in 1 \u2014 hole in one!", StrokeNews.of(shot(Outcome.HOLED, 3, 0.5),
                new PlayerState(3, 0.5, 1, 0, PlayerStatus.HOLED), "Bob", true, 2, 3, 0.5));
        // 1.2, 0.3 is hypot(1.8, 0.2) = 1.811 m from the hole at (3, 0.5): a distance, never a position.
        String stopped = StrokeNews.of(shot(Outcome.STOPPED, 1.2, 0.3), rolling, "Cy", true, null, 3, 0.5);
        assertEquals("Cy: 1.8 m to the hole", stopped);
        assertFalse(stopped.contains("("), "no coordinates");
        assertEquals("In the water: +1 stroke \u2014 the stroke limit: picked up",
                StrokeNews.of(shot(Outcome.WATER, 0, 0), new PlayerState(-3, 0, 5, 5, PlayerStatus.PICKED_UP), "Ann",
                        false, 3, 3, 0.5));
    }

    @Test
    void scoreNamesAgainstPar() {
        assertEquals("hole in one!", StrokeNews.scoreName(1, 3));
        assertEquals("albatross!", StrokeNews.scoreName(2, 5));
        assertEquals("eagle!", StrokeNews.scoreName(2, 4));
        assertEquals("birdie!", StrokeNews.scoreName(2, 3));
        assertEquals("par", StrokeNews.scoreName(3, 3));
        assertEquals("bogey", StrokeNews.scoreName(4, 3));
        assertEquals("double bogey", StrokeNews.scoreName(5, 3));
        assertEquals("triple bogey", StrokeNews.scoreName(6, 3));
        assertEquals("5 over par", StrokeNews.scoreName(8, 3));
        assertEquals("4 strokes", StrokeNews.scoreName(4, null), "a course without par");
    }
}
