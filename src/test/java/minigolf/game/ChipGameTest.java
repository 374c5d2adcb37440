package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Chips in the game: played, saved, loaded, replayed to the bit; old saves (no vz) load as putts; bots chip. */
class ChipGameTest {
    @TempDir
    Path dir;

    static World island() throws Exception {
        return RoundLoader.load(RoundFilesTest.rounds().resolve("meadowbrook-9.json")).hole(4).world();
    }

    @Test
    void aChipFliesOverThePondAndIsRecordedWithItsVz() throws Exception {
        World w = island();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 8); // from the tee itself
        double[] ace = RoundFilesTest.HOLE_IN_ONE[4];
        ShotRecord r = g.play(ace[0], ace[1], ace[2]);
        assertEquals(Outcome.HOLED, r.outcome(), "the island's ace");
        assertEquals(ace[2], r.vz(), 0, "the record keeps vz exactly");
        assertTrue(r.isChip());
        // The same speed as a putt ends in the pond: it was the flight that carried it.
        Game putt = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Bob")), 8);
        assertEquals(Outcome.WATER, putt.play(Math.sqrt(ace[0] * ace[0] + ace[2] * ace[2]), 0).outcome());
    }

    @Test
    void aSavedGameWithChipsRoundTripsAndItsReplayEndsToTheBit() throws Exception {
        World w = island();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 6);
        java.util.Random random = new java.util.Random(5);
        int chips = 0;
        while (!g.isOver()) {
            double a = Math.toRadians(-20 + 40 * random.nextDouble()), speed = 2.5 + 2.5 * random.nextDouble();
            double[] v = Loft.velocity(speed * Math.cos(a), speed * Math.sin(a), 5 * (2 + random.nextInt(11)), 5);
            g.play(v[0], v[1], v[2]);
            chips++;
        }
        assertTrue(chips >= 4, "strokes: " + chips);
        assertTrue(g.history().stream().allMatch(ShotRecord::isChip));
        assertTrue(HoleReplay.of(g).matchesPlay(), "replayed in play");
        Path file = dir.resolve("chips.json");
        SavedGames.save(g, file);
        assertTrue(Files.readString(file).contains("\"velocity\" : [ "), "written");
        Game loaded = SavedGames.load(file).resume();
        assertEquals(g.state(), loaded.state(), "every vz read back exactly");
        assertTrue(HoleReplay.of(loaded).matchesPlay(), "the replay of the loaded game ends to the bit where play ended");
        // The check is not blind: a chip 1e-9 m/s steeper is another stroke.
        ShotRecord first = g.history().get(0);
        List<ShotRecord> changed = new java.util.ArrayList<>(g.history());
        changed.set(0, new ShotRecord(first.player(), first.startX(), first.startY(), first.vx(), first.vy(), first.vz() + 1e-9,
                first.outcome(), first.endX(), first.endY()));
        assertFalse(new HoleReplay(w, SimulationSettings.DEFAULT, changed).matchesPlay());
    }

    @Test
    void aChipInFlightIsSavedAndFliesAgainOnLoad() throws Exception {
        World w = island();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 6);
        double[] ace = RoundFilesTest.HOLE_IN_ONE[4];
        g.startShot(ace[0], ace[1], ace[2], null);
        for (int i = 0; i < 10; i++) g.activeStroke().step();
        assertTrue(g.activeStroke().isFlying(), "saved mid-air");
        Game loaded = SavedGames.parse(SavedGames.toJson(g), "mid-air.json").resume();
        assertTrue(loaded.activeStroke().isFlying(), "restarted from the tee, launched again");
        assertEquals(Outcome.HOLED, loaded.finishShotNow().outcome());
        assertEquals(Outcome.HOLED, g.finishShotNow().outcome());
        assertEquals(g.state(), loaded.state());
    }

    @Test
    void anOldSaveWithoutVzLoadsAsPutts() throws Exception {
        Game g = new Game(GameTest.FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 7);
        g.play(1.0, 0.2);
        g.startShot(1.5, -0.1);
        String json = SavedGames.toJson(g);
        // Putts are written as two numbers, exactly as files from before chips were.
        assertTrue(json.contains("\"velocity\" : [ 1.0, 0.2 ]"), json);
        assertTrue(json.contains("\"velocity\" : [ 1.5, -0.1 ]"), json);
        Game loaded = SavedGames.parse(json, "old.json").resume();
        assertEquals(0, loaded.history().get(0).vz(), 0);
        assertFalse(loaded.activeStroke().isFlying());
        assertEquals(g.state(), loaded.state());
        SaveGameException e = assertThrows(SaveGameException.class,
                () -> SavedGames.parse(json.replace("[ 1.0, 0.2 ]", "[ 1.0, 0.2, -1.0 ]"), "bad.json"));
        assertEquals("bad.json: history[0].velocity[2]: must be 0 or more (the ball is hit upwards or along the ground)", e.getMessage());
    }

    @Test
    void theGameBotChipsOntoTheIsland() throws Exception {
        World w = island();
        ShotPlanner planner = BotCatalog.planner("planner");
        BotTurn turn = new BotTurn(planner, w, SimulationSettings.DEFAULT, w.course().start().x(), w.course().start().y(), 0, 1L);
        turn.join(60_000);
        assertTrue(turn.isDone());
        assertNull(turn.failure());
        double[] v = turn.shot();
        assertEquals(3, v.length);
        assertTrue(v[2] > 0, "the planner's chip stage plays a chip in the game: vz = " + v[2]);
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.bot("Robo", "planner")), 6);
        ShotRecord r = g.play(v[0], v[1], v[2]);
        assertNotEquals(Outcome.WATER, r.outcome(), "over the pond, not into it");
    }
}
