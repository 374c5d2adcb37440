package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import minigolf.course.HoleRule;
import minigolf.theme.Themes;
import org.junit.jupiter.api.Test;

/**
 * The three themed worlds' rounds (tools/generate_worlds.py): 18 holes each, every hole its own idea
 * in its world, railed, with the capture rule and a par of 2 to 4. The pars themselves are checked
 * by `minigolf par-check` (docs/worlds.md); here a cheap sample.
 */
class WorldRoundsTest {
    static Round load(String world) throws Exception {
        return RoundLoader.load(RoundFilesTest.rounds().resolve(world + "-18.json"));
    }

    @Test
    void eachWorldIsARoundOf18DistinctHolesInThatWorld() throws Exception {
        Set<String> all = new HashSet<>();
        for (String world : new String[]{"seaside", "canyon", "winter"}) {
            Round r = load(world);
            assertEquals(18, r.size(), world);
            assertEquals(Themes.byId(world).title(), r.name());
            Set<String> names = new HashSet<>();
            for (Round.Hole h : r.holes()) {
                var c = h.world().course();
                assertEquals(world, c.world(), h.course());
                assertTrue(names.add(c.name()), "one idea per hole: " + c.name());
                assertTrue(all.add(c.name()), "no name shared between worlds: " + c.name());
                assertEquals(HoleRule.CAPTURE, h.world().hole().rule(), h.course());
                assertTrue(h.par() >= 2 && h.par() <= 4, h.course() + " par " + h.par());
                assertTrue(c.obstacles().size() >= 4, h.course() + " has rails");
                assertTrue(h.course().startsWith("../worlds/" + world + "/"), h.course());
            }
            assertTrue(r.par() >= 40 && r.par() <= 54, world + " par " + r.par());
            // The docs say the same par.
            String docs = java.nio.file.Files.readString(RoundFilesTest.rounds().resolve("../../docs/worlds.md").normalize());
            assertTrue(docs.contains("| `" + world + "` | " + r.name() + " | " + r.par() + " |"), world + ": docs/worlds.md's par");
            String readme = java.nio.file.Files.readString(RoundFilesTest.rounds().resolve("../../README.md").normalize());
            assertTrue(readme.contains("**" + r.name() + "** (par " + r.par() + ")"), world + ": README's par");
        }
    }

    @Test
    void aSampleOfHolesIsPlayableByTheProOpponentWithinPar() throws Exception {
        // The first hole of each world, 2 seeds: the full check (10 seeds, every hole) is par-check's.
        ParCheck.Opponent pro = ParCheck.Opponent.parse("pro", ParCheck.PRO);
        ParCheck.Settings s = new ParCheck.Settings(2, 8, 40_000, 0, 0, 1);
        for (String world : new String[]{"seaside", "canyon", "winter"}) {
            Round r = load(world);
            ParCheck.Games g = ParCheck.games(r.hole(0).world(), pro, s);
            assertEquals(0, g.notHoled(), world);
            assertTrue(g.mean() <= r.hole(0).par(), world + " hole 1: " + g.mean());
        }
    }
}
