package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The high-score table per round and personal bests per hole and round: ordering, the cut at 10, the file round trip. */
class HighScoresTest {
    @TempDir
    Path dir;

    private static RoundScorecard card(String round, List<String> names, int[]... perPlayer) {
        List<RoundScorecard.Row> rows = new java.util.ArrayList<>();
        for (int i = 0; i < names.size(); i++) rows.add(new RoundScorecard.Row(names.get(i), perPlayer[i]));
        return new RoundScorecard(round, new int[]{2, 3}, rows, true);
    }

    @Test
    void tablesAndPersonalBestsRoundTripThroughTheFile() throws Exception {
        HighScores h = new HighScores();
        List<Player> ab = List.of(Player.human("Ann"), Player.human("Bob"));
        LocalDate d1 = LocalDate.of(2026, 11, 1), d2 = LocalDate.of(2026, 11, 2);
        assertEquals(List.of(new HighScores.Achievement("Bob", "hole in one!")), h.recordHole("R", 0, ab, new int[]{3, 1}));
        List<HighScores.Achievement> news = h.recordHole("R", 0, ab, new int[]{2, 2});
        assertEquals(List.of(new HighScores.Achievement("Ann", "personal best on hole 1 (2, was 3)")), news);
        assertEquals(2, h.personalBest("R", 0, "Ann"));
        assertEquals(1, h.personalBest("R", 0, "Bob"));
        assertNull(h.personalBest("R", 1, "Ann"));

        h.recordRound("R", card("R", List.of("Ann", "Bob"), new int[]{2, 3}, new int[]{1, 3}), ab, d1);
        news = h.recordRound("R", card("R", List.of("Ann", "Bob"), new int[]{2, 2}, new int[]{3, 3}), ab, d2);
        assertTrue(news.contains(new HighScores.Achievement("Ann", "personal best round 4 (was 5)")), news.toString());
        assertTrue(news.contains(new HighScores.Achievement("Ann", "high score #2")), news.toString());
        assertTrue(news.contains(new HighScores.Achievement("Bob", "high score #4")), news.toString());
        // Equal totals: the earlier date first.
        assertEquals(List.of(new HighScores.Entry("Bob", 4, d1), new HighScores.Entry("Ann", 4, d2),
                new HighScores.Entry("Ann", 5, d1), new HighScores.Entry("Bob", 6, d2)), h.table("R"));
        assertEquals(4, h.personalBest("R", "Bob"));

        Path file = HighScores.file(dir);
        h.save(file);
        HighScores back = HighScores.load(file);
        assertEquals(h.table("R"), back.table("R"));
        assertEquals(h.toJson(), back.toJson());
        assertEquals(1, back.personalBest("R", 0, "Bob"));
        assertEquals(List.of(), back.table("other round"));
    }

    @Test
    void theTableKeepsTheBestTen() {
        HighScores h = new HighScores();
        List<Player> one = List.of(Player.human("Cy"));
        for (int score = 20; score >= 5; score--) {
            h.recordRound("R", card("R", List.of("Cy"), new int[]{score}), one, LocalDate.of(2026, 1, 1));
        }
        List<HighScores.Entry> t = h.table("R");
        assertEquals(10, t.size());
        assertEquals(5, t.get(0).score());
        assertEquals(14, t.get(9).score());
        List<HighScores.Achievement> news = h.recordRound("R", card("R", List.of("Cy"), new int[]{30}), one, LocalDate.of(2026, 1, 2));
        assertTrue(news.isEmpty(), "a score below the table is no achievement: " + news);
    }

    @Test
    void aBrokenFileIsOneLine() throws Exception {
        Path file = HighScores.file(dir);
        Files.writeString(file, "{\"format\": 1, \"kind\": \"minigolf-high-scores\", \"rounds\": {\"R\": {\"table\":"
                + " [{\"name\": \"Ann\", \"score\": 4, \"date\": \"yesterday\"}], \"players\": {}}}}");
        SaveGameException e = assertThrows(SaveGameException.class, () -> HighScores.load(file));
        assertEquals(file + ": rounds.R.table[0].date: must be a date like 2026-11-24, got \"yesterday\"", e.getMessage());
        assertEquals(List.of(), HighScores.load(dir.resolve("none.json")).table("R"));
        // Names are shown on the card: a player's 24 characters, a round's 128, at most.
        Files.writeString(file, "{\"format\": 1, \"kind\": \"minigolf-high-scores\", \"rounds\": {\"R\": {\"table\":"
                + " [{\"name\": \"" + "A".repeat(100_000) + "\", \"score\": 4, \"date\": \"2026-11-24\"}], \"players\": {}}}}");
        assertEquals(file + ": rounds.R.table[0].name: too long: 100000 characters (the limit is 24)",
                assertThrows(SaveGameException.class, () -> HighScores.load(file)).getMessage());
        Files.writeString(file, "{\"format\": 1, \"kind\": \"minigolf-high-scores\", \"rounds\": {\"" + "R".repeat(129)
                + "\": {\"table\": [], \"players\": {}}}}");
        assertEquals(file + ": rounds: too long: 129 characters (the limit is 128)",
                assertThrows(SaveGameException.class, () -> HighScores.load(file)).getMessage());
    }
}
