package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import minigolf.bot.Shot;
import minigolf.bot.level.Level;
import org.junit.jupiter.api.Test;

/** The seeds a game gives its bots: a level misplays each stroke of each hole afresh. */
class BotTurnSeedTest {
    @Test
    void everyHoleStrokeAndSeatHasItsOwnSeedAndAGameRepeatsItself() {
        Set<Long> seen = new HashSet<>();
        for (int hole = 0; hole < 18; hole++) {
            for (int strokes = 0; strokes < 12; strokes++) {
                for (int seat = 0; seat < Game.MAX_PLAYERS; seat++) seen.add(BotTurn.seed(42, hole, strokes, seat));
            }
        }
        assertEquals(18 * 12 * Game.MAX_PLAYERS, seen.size());
        assertEquals(BotTurn.seed(42, 7, 3, 1), BotTurn.seed(42, 7, 3, 1));
        assertNotEquals(BotTurn.seed(42, 7, 3, 1), BotTurn.seed(43, 7, 3, 1));
    }

    /**
     * Hard's first strokes over four 18-hole rounds: the direction errors drawn from these seeds
     * spread as the level's error says (sigma 1.5 degrees), where the old seed (31 x strokes
     * played + seat) gave one error for every hole and every round (spread 0).
     */
    @Test
    void aLevelsFirstStrokesOnARoundsHolesAreIndependentDraws() {
        double sum = 0, sumSq = 0;
        int n = 0;
        for (long game = 1; game <= 4; game++) {
            for (int hole = 0; hole < 18; hole++) {
                Shot played = Level.HARD.error().play(new Shot(2, 0, 0), new SplittableRandom(BotTurn.seed(game, hole, 0, 1)), 5);
                double angle = Math.atan2(played.vy(), played.vx());
                sum += angle;
                sumSq += angle * angle;
                n++;
            }
        }
        double sd = Math.sqrt((sumSq - sum * sum / n) / (n - 1)), sigma = Level.HARD.error().angle();
        assertTrue(sd > 0.7 * sigma && sd < 1.3 * sigma, "spread " + Math.toDegrees(sd) + " degrees against "
                + Math.toDegrees(sigma));
    }
}
