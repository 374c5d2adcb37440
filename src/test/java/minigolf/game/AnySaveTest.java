package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** "Load saved game" reads a file once and gets a round or a game, whichever it holds, or one line saying why not. */
class AnySaveTest {
    @TempDir
    Path dir;

    private static World flat() throws Exception {
        return World.parse("{\"format\": 1, \"name\": \"Flat\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]}, \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-3, 0], \"hole\": {\"position\": [1, 0], \"radius\": 0.1}}", "flat");
    }

    @Test
    void aRoundFileIsARoundAndAGameFileAGame() throws Exception {
        World w = flat();
        RoundGame rg = new RoundGame(new Round("R", List.of(new Round.Hole("a.json", 2, w)), "test"), SimulationSettings.DEFAULT,
                List.of(Player.human("Ann")), 10);
        Path roundFile = dir.resolve("round.json"), gameFile = dir.resolve("game.json");
        SavedRounds.save(rg, roundFile);
        SavedGames.save(new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Bob")), 10), gameFile);
        SavedRounds.AnySave r = SavedRounds.loadAny(roundFile), g = SavedRounds.loadAny(gameFile);
        assertNotNull(r.round());
        assertNull(r.game());
        assertEquals("R", r.round().round().name());
        assertNull(g.round());
        assertEquals("Bob", g.game().resume().players().get(0).name());
    }

    @Test
    void aMissingOrBrokenFileIsOneLine() throws Exception {
        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{ not json");
        SaveGameException e = assertThrows(SaveGameException.class, () -> SavedRounds.loadAny(broken));
        assertTrue(e.getMessage().startsWith(broken.toString()), e.getMessage());
        assertEquals(1, e.getMessage().lines().count());
        assertThrows(SaveGameException.class, () -> SavedRounds.loadAny(dir.resolve("none.json")));
    }
}
