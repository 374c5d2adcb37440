package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.Shot;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The dense first-shot sweep on its own: the aces it finds are replayed on the engine. */
class DenseSweepTest {
    private static Outcome replay(Stroke s, Shot shot) {
        return new Simulator(s.world, SimulationSettings.DEFAULT).simulate(s.px, s.py, shot.vx(), shot.vy()).outcome();
    }

    @Test
    void onFlatGroundTheSlowedShotStopsWhereTheFastOnePassedNearest() {
        // flat-7m: mu_k 0.1, the hole 7 m away. A 5 m/s putt straight at it passes over the hole at
        // sqrt(25 - 2 mu g 7) m/s; cut by that, it needs sqrt(2 mu g 7) = 3.706 m/s: the closed form.
        Stroke s = StagesTest.atStart("flat-7m");
        DenseSweep.Pass p = new DenseSweep.Pass(Shot.of(5, 0), 0, Math.sqrt(25 - 2 * 0.1 * 9.81 * 7));
        assertEquals(Math.sqrt(2 * 0.1 * 9.81 * 7), DenseSweep.stopWhereNearest(p).speed(), 1e-12);
        assertEquals(Outcome.HOLED, replay(s, DenseSweep.stopWhereNearest(p)));
        assertTrue(Flatness.isFlat(s.world));
        assertFalse(Flatness.isFlat(CycleGuardTest.load("hills-water")));
    }

    @Test
    void itFindsTheAcesOfTheBenchCoursesOnItsOwn() {
        for (String course : new String[] {"water-bank", "maze-c", "lake-bowl", "sine-cross-limit"}) {
            Stroke s = StagesTest.atStart(course);
            DenseSweep sweep = new DenseSweep(s);
            Shot ace = sweep.holeInOne();
            assertNotNull(ace, course);
            assertEquals(Outcome.HOLED, replay(s, ace), course);
            assertTrue(s.sim.count() <= sweep.cost(), course + ": " + s.sim.count() + " shots, at most " + sweep.cost());
        }
    }

    @Test
    void itCostsOneShotPerDegreeOnFlatGroundAndStaysOutWhenTheBudgetIsShort() {
        Stroke flat = StagesTest.atStart("maze-b");
        assertEquals(360 + 8 * 7 + 4 * 17, new DenseSweep(flat).cost());
        Stroke hills = StagesTest.atStart("hills-water");
        assertEquals(3 * 360 + 8 * 7 * 3 + 4 * 17, new DenseSweep(hills).cost());
        // maze-b has no ace (the exhaustive search: 3 strokes at best): the sweep spends what it says.
        assertNull(new DenseSweep(flat).holeInOne());
        assertTrue(flat.sim.count() <= new DenseSweep(flat).cost(), flat.sim.count() + " shots");
    }
}
