package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import minigolf.game.HighScores.Achievement;
import org.junit.jupiter.api.Test;

/**
 * The high scores' news at the end of a round, as a player reads it: one group per player, and no
 * second "hole in one!" (the 18-hole final card said "Bot (Hard): hole in one!; Bot (Hard): first
 * round: 25; Bot (Hard): high score #1; ..." right after another player's birdie).
 */
class AchievementNewsTest {
    @Test
    void groupedByPlayerWithoutTheHoleInOneTheStrokeAlreadyAnnounced() {
        List<Achievement> news = List.of(new Achievement("Ann", "hole in one!"), new Achievement("Ann", "first round 25"),
                new Achievement("Bob", "first round 57"), new Achievement("Ann", "high score #1"),
                new Achievement("Bob", "high score #2"));
        assertEquals("Ann: first round 25, high score #1  \u00b7  Bob: first round 57, high score #2", PlayerFiles.news(news));
    }

    @Test
    void aHoleInOneAloneSaysNothingMore() {
        assertEquals("", PlayerFiles.news(List.of(new Achievement("Ann", "hole in one!"))));
    }
}
