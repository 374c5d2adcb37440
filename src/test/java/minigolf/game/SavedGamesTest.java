package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.physics.Integrator;
import minigolf.physics.SimulationSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SavedGamesTest {
    @TempDir
    Path dir;

    private static Game threePlayers() {
        return new Game(GameTest.FLAT, SimulationSettings.DEFAULT.withIntegrator(Integrator.RK2),
                List.of(Player.human("Ann"), Player.bot("Robo", "planner"), Player.human("Cy")), 7);
    }

    /** The same shots on both games, chosen from the state (so a difference in state shows). */
    private static void playOn(Game g, int shots) {
        for (int i = 0; i < shots && !g.isOver(); i++) {
            PlayerState s = g.player(g.currentPlayer());
            double[] v = GameTest.shot(s.x(), s.y(), 3, 0.5, 0.6 + 0.1 * (i % 4));
            g.play(v[0], v[1]);
        }
    }

    @Test
    void saveLoadContinueGivesTheSameState() throws Exception {
        Game original = threePlayers();
        playOn(original, 3);
        original.play(-3.9, 0.1); // out of bounds for the current player: a penalty in the saved state
        Path file = dir.resolve("game.json");
        SavedGames.save(original, file);

        Game resumed = SavedGames.load(file).resume();
        assertEquals(original.state(), resumed.state(), "players, balls, strokes, history, turn");
        assertEquals(original.currentPlayer(), resumed.currentPlayer());
        assertEquals(original.world().course(), resumed.world().course(), "the course is embedded");

        playOn(original, 20);
        playOn(resumed, 20);
        assertEquals(original.state(), resumed.state());
        assertEquals(original.scorecard(), resumed.scorecard());
        assertTrue(original.isOver());
    }

    @Test
    void aStrokeInFlightIsReplayedFromItsStart() throws Exception {
        Game original = threePlayers();
        playOn(original, 1);
        original.startShot(2.0, 0.3);
        for (int i = 0; i < 20; i++) original.activeStroke().step();
        Path file = dir.resolve("rolling.json");
        SavedGames.save(original, file);

        Game resumed = SavedGames.load(file).resume();
        assertTrue(resumed.isShotInFlight());
        assertEquals(0, resumed.activeStroke().steps(), "restarted from where it was hit");
        original.finishShotNow();
        resumed.finishShotNow();
        assertEquals(original.state(), resumed.state());
    }

    @Test
    void badFilesGiveOneLineMessages() throws Exception {
        Game g = threePlayers();
        String good = SavedGames.toJson(g);
        assertProblem(dir.resolve("game.json") + ": cannot read: no such file", () -> SavedGames.load(dir.resolve("game.json")));
        assertProblem("x.json: not valid JSON at line 1, column 2", () -> SavedGames.parse("{", "x.json"));
        assertProblem("x.json: kind: must be \"minigolf-saved-game\" (is this a saved game?)",
                () -> SavedGames.parse(good.replace("minigolf-saved-game", "course"), "x.json"));
        assertProblem("x.json: players[1].kind: must be human or bot",
                () -> SavedGames.parse(good.replace("\"bot\",", "\"robot\","), "x.json"));
        assertProblem("x.json: players[0].ball: lies outside the course (its bounds or a deleted cell)",
                () -> SavedGames.parse(good.replaceFirst("\"ball\" : \\[ -3\\.0", "\"ball\" : [ -30.0"), "x.json"));
        assertProblem("x.json: course.hole.radius: must be > 0, got -0.1",
                () -> SavedGames.parse(good.replace("\"radius\" : 0.1", "\"radius\" : -0.1"), "x.json"));
        assertProblem("x.json: simulation.dt: must be a number, got null",
                () -> SavedGames.parse(good.replaceFirst("\"dt\" : [0-9.eE-]+", "\"dt\" : null"), "x.json"));
        assertProblem("x.json: simulation.dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 4.9E-324",
                () -> SavedGames.parse(good.replaceFirst("\"dt\" : [0-9.eE-]+", "\"dt\" : 4.9e-324"), "x.json"));
        assertProblem("x.json: strokeLimit: must be 1 to 99, got 99999999999",
                () -> SavedGames.parse(good.replace("\"strokeLimit\" : 7", "\"strokeLimit\" : 99999999999"), "x.json"));
        com.fasterxml.jackson.databind.node.ObjectNode tree = (com.fasterxml.jackson.databind.node.ObjectNode) JsonFields.MAPPER.readTree(good);
        tree.remove("simulation");
        String noSimulation = tree.toString();
        assertProblem("x.json: simulation: is missing", () -> SavedGames.parse(noSimulation, "x.json"));
        assertProblem("x.json: strokeLimit: must be 1 to 99, got 0",
                () -> SavedGames.parse(good.replace("\"strokeLimit\" : 7", "\"strokeLimit\" : 0"), "x.json"));
        assertProblem("x.json: players[2].penalties: must be 0 to 0, got 1",
                () -> SavedGames.parse(good.replaceFirst("(\"Cy\"[^}]*\"penalties\" : )0", "$11"), "x.json"));
    }

    @Test
    void theBotsSeedIsSavedAndASaveWithoutItResumesWithSeedZero() throws Exception {
        Game withBots = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.bot("Robo", "hard")),
                7, null, 0, -1234567890123L);
        String json = SavedGames.toJson(withBots);
        assertTrue(json.contains("\"botSeed\" : -1234567890123"), json);
        assertEquals(-1234567890123L, SavedGames.parse(json, "x.json").resume().botSeed());
        // Saves from before the field: the documented default, 0 (docs/playing.md).
        com.fasterxml.jackson.databind.node.ObjectNode old = (com.fasterxml.jackson.databind.node.ObjectNode) JsonFields.MAPPER.readTree(json);
        old.remove("botSeed");
        assertEquals(0, SavedGames.parse(old.toString(), "x.json").resume().botSeed());
        assertProblem("x.json: botSeed: must be a whole number",
                () -> SavedGames.parse(json.replace("-1234567890123", "1.5"), "x.json"));
        assertProblem("x.json: botSeed: must be a whole number",
                () -> SavedGames.parse(json.replace("-1234567890123", "99999999999999999999"), "x.json"));
        // Without a computer opponent the seed means nothing and the save does not hold it.
        Game people = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 7, null, 0, 42);
        assertEquals(0, people.botSeed());
        assertTrue(!SavedGames.toJson(people).contains("botSeed"));
    }

    @Test
    void saveIsAtomicAndLeavesNoTemporaryFiles() throws Exception {
        Path file = dir.resolve("g.json");
        Files.writeString(file, "old");
        SavedGames.save(threePlayers(), file);
        assertTrue(Files.readString(file).contains("minigolf-saved-game"));
        try (var files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
        Path blocked = dir.resolve("a-dir");
        Files.createDirectory(blocked);
        SaveGameException e = assertThrows(SaveGameException.class, () -> SavedGames.save(threePlayers(), blocked));
        assertTrue(e.getMessage().startsWith(blocked + ": cannot replace the file"), e.getMessage());
    }

    private static void assertProblem(String expectedStart, org.junit.jupiter.api.function.Executable call) {
        SaveGameException e = assertThrows(SaveGameException.class, call);
        assertNotNull(e.getMessage());
        assertTrue(e.getMessage().startsWith(expectedStart), "got: " + e.getMessage());
        assertEquals(1, e.getMessage().lines().count());
    }
}
