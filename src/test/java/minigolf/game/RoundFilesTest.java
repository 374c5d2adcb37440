package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import minigolf.course.HoleRule;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The bundled rounds: the 18-hole round and its front nine load, every hole is its own course with
 * the capture rule, and every hole has a hole in one that is possible but hard. The holing shots
 * below were found by {@link HoleInOneSweep} (720 directions x 60 speeds from the tee; the middle of
 * the largest success region); the sweep's share of holing strokes, 0.002% to 2.8%, is in docs/playing.md.
 */
public class RoundFilesTest {
    /** One first stroke (vx, vy) per hole of meadowbrook-18 that holes in one; (vx, vy, vz) where it is a chip. */
    public static final double[][] HOLE_IN_ONE = {
            {4.2930808673884890, 1.6051171641058921},
            {3.9667667014561756, 3.0438071450436030},
            {3.5664619361068257, -1.1588137289060536},
            {3.7544468696578788, 2.6288919999422940},
            {4.117273506839396, 0.0, 2.5727580278521773}, // a chip over the pond (AceSweep along the line to the cup)
            {3.8974802591409405, -0.89980421737546130},
            {3.8333333333333335, 0.0000000000000000},
            {2.9835656861048196, -0.31358538980296025},
            {3.1803911013888198, 3.8581229169386000},
            {3.6914433169206120, 2.9892718574867274},
            {3.7562054803753590, 3.0417152234075470},
            {3.6119283366001470, 3.0848782295683725},
            {3.8354368893851687, 1.6280463687053073},
            {3.7858222447676630, 2.2747514975194060},
            {2.7960007107199350, 1.4866599488219874},
            {2.3901216697912990, 0.35720607689655900},
            {3.6042044086648100, 2.2521568729911210},
            {4.0853622077378550, 1.1714587622222465}
    };

    private static double vz(double[] v) {
        return v.length > 2 ? v[2] : 0;
    }

    /** The holes of the 18 whose ace is a chip: at least one in the front nine (the island green). */
    @Test
    void aChipOverWaterIsPartOfBothRounds() throws Exception {
        Round r9 = load("meadowbrook-9.json");
        int island = 4;
        assertEquals("Island Green", r9.hole(island).world().course().name());
        assertEquals(3, HOLE_IN_ONE[island].length, "the island's ace is a chip");
        World w = r9.hole(island).world();
        // No putt from the tee reaches the island: every one of 72 directions x 15 speeds ends in the pond or short.
        assertEquals(0, HoleInOneSweep.sweep(w, 72, 15).holed(), "no putt holes in one");
        double sx = w.course().start().x(), sy = w.course().start().y();
        boolean anyPuttOnIsland = false;
        Simulator sim = new Simulator(w, SimulationSettings.DEFAULT);
        for (int k = 1; k <= 50; k++) {
            var res = sim.simulate(sx, sy, 0.1 * k, 0);
            if (res.outcome() == Outcome.STOPPED && Math.hypot(res.endX() - 1.8, res.endY()) < 0.6) anyPuttOnIsland = true;
        }
        assertFalse(anyPuttOnIsland, "a putt straight at the cup never stops on the island");
    }

    static Path rounds() {
        return Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "rounds");
    }

    private static Round load(String file) throws Exception {
        return RoundLoader.load(rounds().resolve(file));
    }

    @Test
    void theBundledRoundsHave18And9DistinctHoles() throws Exception {
        Round r18 = load("meadowbrook-18.json"), r9 = load("meadowbrook-9.json");
        assertEquals(18, r18.size());
        assertEquals(9, r9.size());
        for (int i = 0; i < 9; i++) assertEquals(r18.hole(i).world().course(), r9.hole(i).world().course(), "front nine hole " + (i + 1));
        Set<String> names = new HashSet<>();
        for (Round.Hole h : r18.holes()) {
            assertTrue(names.add(h.world().course().name()), "one idea per hole: " + h.world().course().name());
            assertEquals(HoleRule.CAPTURE, h.world().hole().rule(), h.course());
            assertTrue(h.par() >= 2 && h.par() <= 3, h.course() + " par " + h.par());
            assertFalse(h.world().course().obstacles().isEmpty(), h.course() + " has rails");
        }
        assertEquals(46, r18.par());
        assertEquals(24, r9.par());
    }

    @Test
    void everyHoleHasAHoleInOne() throws Exception {
        Round r = load("meadowbrook-18.json");
        assertEquals(r.size(), HOLE_IN_ONE.length);
        for (int i = 0; i < r.size(); i++) {
            World w = r.hole(i).world();
            Simulator sim = new Simulator(w, SimulationSettings.DEFAULT);
            double[] v = HOLE_IN_ONE[i];
            assertEquals(Outcome.HOLED, sim.simulate(w.course().start().x(), w.course().start().y(), v[0], v[1], vz(v)).outcome(),
                    "hole " + (i + 1) + " " + w.course().name());
        }
    }

    @Test
    void holesInOneAreHard() throws Exception {
        // A coarse sweep (5 degrees x 1/15 of the top speed): on every hole under 5% of first strokes
        // hole, and on some none at all; and next to every hole's ace (5 degrees, 10% of the speed) a
        // stroke misses.
        Round r = load("meadowbrook-18.json");
        int withAnyHoled = 0;
        for (int i = 0; i < r.size(); i++) {
            HoleInOneSweep.Result res = HoleInOneSweep.sweep(r.hole(i).world(), 72, 15);
            assertTrue(res.fraction() < 0.05, "hole " + (i + 1) + ": " + res.holed() + " of " + res.total());
            if (res.holed() > 0) withAnyHoled++;
            World w = r.hole(i).world();
            Simulator sim = new Simulator(w, SimulationSettings.DEFAULT);
            double[] v = HOLE_IN_ONE[i];
            // Turned 5 degrees either way, or 10% faster or slower (the whole velocity, the loft kept).
            double a = Math.atan2(v[1], v[0]), ground = Math.hypot(v[0], v[1]), s = Math.hypot(ground, vz(v));
            int misses = 0;
            for (double[] d : List.of(new double[]{Math.toRadians(5), 1}, new double[]{-Math.toRadians(5), 1},
                    new double[]{0, 1.1}, new double[]{0, 0.9})) {
                double k = Math.min(w.physics().maxSpeed(), s * d[1]) / s;
                if (sim.simulate(w.course().start().x(), w.course().start().y(), k * ground * Math.cos(a + d[0]),
                        k * ground * Math.sin(a + d[0]), k * vz(v)).outcome() != Outcome.HOLED) misses++;
            }
            assertTrue(misses >= 1, "hole " + (i + 1) + ": no stroke near the ace misses");
        }
        assertTrue(withAnyHoled < r.size(), "a coarse sweep finds no ace on some holes");
    }
}
