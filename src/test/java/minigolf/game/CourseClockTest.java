package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The course clock is part of a game's state (issue 24): strokes on a course with moving obstacles
 * are played at the game's clock, which runs on between them; saves keep it, and hot-seat replays
 * end every stroke exactly (to the bit) where it ended in play.
 */
class CourseClockTest {
    @TempDir
    Path dir;

    static World windmill() throws Exception {
        return World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "practice", "windmill.json"));
    }

    @Test
    void hotSeatOnTheWindmillReplaysToTheBitAfterSaving() throws Exception {
        World w = windmill();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 6);
        Random random = new Random(24);
        double before = 0;
        while (!g.isOver()) {
            g.advanceClock(random.nextDouble() * 3); // the players take their time aiming
            double clock = g.clock();
            double a = (random.nextDouble() - 0.5) * 0.4, v = 3 + random.nextDouble() * 2;
            ShotRecord r = g.play(v * Math.cos(a), v * Math.sin(a));
            assertEquals(clock, r.clock(), "the stroke is played at the game's clock");
            assertTrue(g.clock() > clock, "the stroke's own time moves the clock on");
            before = g.clock();
        }
        assertTrue(HoleReplay.of(g).matchesPlay());
        Path file = dir.resolve("windmill.json");
        SavedGames.save(g, file);
        Game loaded = SavedGames.load(file).resume();
        assertEquals(before, loaded.clock());
        assertEquals(g.history(), loaded.history());
        assertTrue(HoleReplay.of(loaded).matchesPlay());
        // The replay is not blind to the clock: the same strokes played half a second later (an eighth of a turn) end elsewhere.
        List<ShotRecord> shifted = new ArrayList<>();
        for (ShotRecord r : g.history()) {
            shifted.add(new ShotRecord(r.player(), r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.outcome(), r.endX(),
                    r.endY(), r.clock() + 0.5));
        }
        assertFalse(new HoleReplay(w, SimulationSettings.DEFAULT, shifted).matchesPlay());
    }

    @Test
    void aStrokeInFlightResumesAtItsMomentOfTheClock() throws Exception {
        World w = windmill();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 6);
        g.advanceClock(1.37);
        g.startShot(4.5, 0.02, null);
        for (int i = 0; i < 20; i++) g.activeStroke().step();
        assertEquals(1.37 + 20 / 60.0, g.clock(), 1e-9);
        Path file = dir.resolve("flight.json");
        SavedGames.save(g, file);
        Game resumed = SavedGames.load(file).resume();
        assertEquals(1.37, resumed.clock(), 0, "restarted from its start");
        ShotRecord a = g.finishShotNow(), b = resumed.finishShotNow();
        assertEquals(a, b);
        assertEquals(1.37, a.clock());
        // Played at another moment the same stroke meets the blades elsewhere.
        Game other = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 6);
        other.advanceClock(1.87);
        ShotRecord c = other.play(4.5, 0.02);
        assertNotEquals(a.endX(), c.endX());
    }

    @Test
    void aSaveWithoutAClockIsAtZeroAndABadClockIsOneLine() throws Exception {
        World w = windmill();
        Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 6);
        String json = SavedGames.toJson(g);
        assertFalse(json.contains("\"clock\""), "a game at clock 0 writes none (files as before)");
        g.advanceClock(2.5);
        String later = SavedGames.toJson(g);
        assertEquals(2.5, SavedGames.parse(later, "x.json").state().clock());
        SaveGameException e = org.junit.jupiter.api.Assertions.assertThrows(SaveGameException.class,
                () -> SavedGames.parse(later.replace("\"clock\" : 2.5", "\"clock\" : -1"), "x.json"));
        assertEquals("x.json: clock: must be 0 or more, got -1.0", e.getMessage());
    }
}
