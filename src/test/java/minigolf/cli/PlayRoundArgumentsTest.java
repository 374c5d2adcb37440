package minigolf.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.Player;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** play --round and --players Bot:NAME: bad input is one line and exit code 2, before any window opens. */
class PlayRoundArgumentsTest {
    @TempDir
    Path dir;

    private static String round(String file) {
        return Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "rounds", file).toString();
    }

    @Test
    void badRoundsAndPlayersAreUserErrors() throws Exception {
        Path broken = dir.resolve("r.json");
        Files.writeString(broken, "{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"nope.json\", \"par\": 2}]}");
        CliRun r = CliRun.of("play", "--round", broken.toString(), "--players", "Ann", "--frames", "1");
        assertEquals(2, r.code());
        assertEquals("minigolf: " + broken + ": holes[0].course: " + dir.resolve("nope.json") + ": cannot read: no such file",
                r.err().strip());
        r = CliRun.of("play", "--round", round("meadowbrook-9.json"), "--players", "Ann,Bot:nobody", "--frames", "1");
        assertEquals(2, r.code());
        assertTrue(r.err().startsWith("minigolf: --players: no bot named 'nobody' (bots: easy, medium, hard, pro, planner"), r.err());
        r = CliRun.of("play", "x.json", "--round", round("meadowbrook-9.json"));
        assertEquals(2, r.code());
        assertEquals("minigolf: give either a COURSE or --round, not both", r.err().strip());
    }

    @Test
    void botSeatsAreNamedByTheirBot() {
        List<Player> p = PlayCommand.seats(List.of("Ann", "Bot:planner", "bot:straight"));
        assertEquals("Ann", p.get(0).name());
        assertFalse(p.get(0).isBot());
        assertEquals("Bot (planner)", p.get(1).name());
        assertEquals("planner", p.get(1).bot());
        assertEquals("Bot 2 (straight)", p.get(2).name());
        assertEquals("straight", p.get(2).bot());
        // a level is named as the New game screen names it
        assertEquals("Bot (Medium)", PlayCommand.seats(List.of("Bot:medium")).get(0).name());
    }
}
