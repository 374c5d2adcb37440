package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import org.junit.jupiter.api.Test;

/** par-check's rules and opponents. */
class ParCheckTest {
    @Test
    void opponentsAreABotAndAVelocityNoise() {
        assertEquals(new ParCheck.Opponent("pro", "planner", 0.03), ParCheck.Opponent.parse("pro", "planner@0.03"));
        assertEquals(new ParCheck.Opponent("m", "planner", 0), ParCheck.Opponent.parse("m", "planner"));
        assertEquals(new ParCheck.Opponent("medium", "medium", 0), ParCheck.Opponent.parse("medium", ParCheck.MEDIUM), "a level");
        assertEquals("planner@0.03", ParCheck.Opponent.parse("pro", "planner@0.03").toString());
        IllegalArgumentException bot = assertThrows(IllegalArgumentException.class, () -> ParCheck.Opponent.parse("--pro", "hal@0.1"));
        assertTrue(bot.getMessage().startsWith("--pro: no bot 'hal' (known: ") && bot.getMessage().contains("planner"), bot.getMessage());
        IllegalArgumentException sigma = assertThrows(IllegalArgumentException.class, () -> ParCheck.Opponent.parse("--pro", "planner@x"));
        assertEquals("--pro: the noise after @ must be a number (m/s), got 'x'", sigma.getMessage());
    }

    private static ParCheck.Games games(int... strokes) {
        int aces = 0;
        for (int s : strokes) if (s == 1) aces++;
        return new ParCheck.Games(strokes, aces, 0);
    }

    @Test
    void aHolePassesWithinTheAllowancesAndNotOtherwise() {
        ParCheck.HoleResult ok = new ParCheck.HoleResult(1, "A", 3, games(4, 5, 4, 5), games(2, 3, 3, 1, 3, 2), 0.001, false);
        assertTrue(ok.passes());
        assertFalse(new ParCheck.HoleResult(1, "A", 3, games(5, 5, 4, 5), games(3), 0, false).mediumPasses(), "4.75 > 4.5");
        assertFalse(new ParCheck.HoleResult(1, "A", 2, games(3), games(3, 2), 0, false).proPasses(), "2.5 > 2");
        ParCheck.HoleResult aces = new ParCheck.HoleResult(1, "A", 2, games(3), games(1, 1, 2), 0, false);
        assertFalse(aces.acesPass(), "2 aces of 3 seeds");
        assertTrue(new ParCheck.HoleResult(1, "A", 2, games(3), games(1, 1, 2), 0, true).acesPass(), "an ace hole");
        assertTrue(new ParCheck.HoleResult(1, "A", 2, games(3), games(1, 2, 2), 0, false).acesPass(), "a third");
        String table = ParCheck.table("R", List.of(ok, aces), ParCheck.Opponent.parse("medium", "planner@0.1"),
                ParCheck.Opponent.parse("pro", "planner@0.03"), new ParCheck.Settings(6, 10, 1000, 0, 0, 1));
        assertTrue(table.contains("| 1 | A | 3 | 4.5 | 2.3 | 1 of 6 | 0.10% | ok |"), table);
        assertTrue(table.contains("pro aces too often"), table);
        assertTrue(table.contains("1 of 2 holes pass."), table);
    }

    @Test
    void theAceSweepFindsNoAceWhereNoStrokeCanHole() throws Exception {
        // Meadowbrook's island green: no putt from the tee reaches the island (RoundFilesTest).
        Round r = RoundLoader.load(RoundFilesTest.rounds().resolve("meadowbrook-9.json"));
        assertEquals(0, ParCheck.aceSweepShare(r.hole(4).world(), 72, 10));
        assertTrue(Double.isNaN(ParCheck.aceSweepShare(r.hole(4).world(), 0, 0)));
    }
}
