package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A hole replayed from its shot history ends, stroke by stroke, exactly (to the bit) where it ended in play. */
class HoleReplayTest {
    @TempDir
    Path dir;

    @Test
    void aReplayedHoleEndsWhereItEndedInPlayToTheBit() throws Exception {
        Round r = RoundLoader.load(RoundFilesTest.rounds().resolve("meadowbrook-18.json"));
        Random random = new Random(11);
        int strokes = 0;
        for (int hole : new int[]{4, 9, 17}) { // island (water), pinball (bumpers), finale (windmill, trees, pond)
            World w = r.hole(hole).world();
            Game g = new Game(w, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 6);
            while (!g.isOver()) {
                double a = random.nextDouble() * 2 * Math.PI, v = 0.5 + random.nextDouble() * 4;
                g.play(v * Math.cos(a), v * Math.sin(a));
            }
            strokes += g.history().size();
            assertTrue(HoleReplay.of(g).matchesPlay(), w.course().name());
            // And from a saved game: the file holds every double exactly.
            Path file = dir.resolve("g" + hole + ".json");
            SavedGames.save(g, file);
            assertTrue(HoleReplay.of(SavedGames.load(file).resume()).matchesPlay(), w.course().name() + " after saving");
            // A stroke hit 1e-9 m/s harder is a different stroke: the check is not blind.
            ShotRecord first = g.history().get(0);
            List<ShotRecord> changed = new java.util.ArrayList<>(g.history());
            changed.set(0, new ShotRecord(first.player(), first.startX(), first.startY(), first.vx() + 1e-9, first.vy(),
                    first.outcome(), first.endX(), first.endY()));
            assertFalse(new HoleReplay(w, SimulationSettings.DEFAULT, changed).matchesPlay(), w.course().name() + " changed");
        }
        assertTrue(strokes > 12, "strokes replayed: " + strokes);
    }
}
