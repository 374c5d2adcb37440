package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.util.List;
import minigolf.physics.SimulationSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Saved games are listed by round or course, players and date, not by file name. */
class SavedGameSummaryTest {
    @TempDir
    Path dir;

    @Test
    void aSavedGameAndASavedRoundAreDescribedByWhatTheyHold() throws Exception {
        LocalDateTime when = LocalDateTime.of(2026, 11, 24, 21, 5);
        FileTime time = FileTime.from(when.atZone(ZoneId.systemDefault()).toInstant());

        Game g = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.bot("Robo", "planner")), 7);
        g.play(1, 0);
        Path game = dir.resolve("game-20261124-210500.json");
        SavedGames.save(g, game);
        Files.setLastModifiedTime(game, time);
        SavedGameSummary s = SavedGameSummary.read(game);
        assertEquals(GameTest.FLAT.course().name(), s.name());
        assertEquals(List.of("Ann", "Robo"), s.players());
        assertEquals(GameTest.FLAT.course().name() + " - Ann, Robo - 2026-11-24 21:05", s.label());

        Round r = RoundLoader.load(RoundFilesTest.rounds().resolve("meadowbrook-9.json"));
        RoundGame rg = new RoundGame(r, SimulationSettings.DEFAULT, List.of(Player.human("Cy")), 8);
        double[] ace = RoundFilesTest.HOLE_IN_ONE[0];
        rg.game().play(ace[0], ace[1]);
        rg.finishHole();
        assertTrue(rg.nextHole());
        Path round = dir.resolve("round-20261124-210500.json");
        SavedRounds.save(rg, round);
        Files.setLastModifiedTime(round, time);
        assertEquals("Meadowbrook Front Nine, hole 2: Dogleg - Cy - 2026-11-24 21:05", SavedGameSummary.cached(round).label());
        assertSame(SavedGameSummary.cached(round), SavedGameSummary.cached(round), "read once while the file is unchanged");

        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{");
        assertEquals("broken.json", SavedGameSummary.read(broken).name(), "an unreadable file: its name");
    }

    /** The list shows what a loaded save could hold, no more: long names are cut, and a FIFO is not read (it would block the menu). */
    @Test
    void namesAreCutAndOnlyRegularFilesAreRead() throws Exception {
        Game g = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 7);
        Path game = dir.resolve("long.json");
        String json = SavedGames.toJson(g).replace("\"" + GameTest.FLAT.course().name() + "\"", "\"" + "c".repeat(100_000) + "\"")
                .replace("\"Ann\"", "\"" + "a".repeat(100_000) + "\"");
        Files.writeString(game, json);
        SavedGameSummary s = SavedGameSummary.read(game);
        assertEquals("c".repeat(125) + "...", s.name());
        assertEquals(List.of("a".repeat(21) + "..."), s.players());
        Path fifo = dir.resolve("fifo.json");
        Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
        org.junit.jupiter.api.Assumptions.assumeTrue(mk.waitFor() == 0, "mkfifo is available");
        assertEquals("fifo.json", assertTimeoutPreemptively(java.time.Duration.ofSeconds(30), () -> SavedGameSummary.read(fifo)).name(),
                "listed by its name, not read (reading a FIFO blocks until someone writes)");
    }
}
