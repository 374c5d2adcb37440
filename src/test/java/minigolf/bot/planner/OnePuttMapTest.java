package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.course.CourseException;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The one-putt map traced backwards from the hole: a point that sees the hole gets a straight
 * putt, a point behind a wall a bank shot off the rim, and from both the map's putt starts a
 * Broyden that holes (replayed on the engine).
 */
class OnePuttMapTest {
    /** Flat, 8 x 4 m, a wall from the bottom rim to y = 0.6 at x = 0 between the left half and the hole. */
    static World screened() {
        String json = """
                {"format": 1, "name": "screened hole", "terrain": {"height": "0"},
                 "bounds": {"min": [-4, -2], "max": [4, 2]},
                 "physics": {"gravity": 9.81, "kineticFriction": 0.1, "staticFriction": 0.2, "maxSpeed": 5, "model": "classic"},
                 "start": [-2, -1], "hole": {"position": [3, -1], "radius": 0.1, "rule": "rest"}, "zones": [],
                 "obstacles": [
                   {"type": "wall", "from": [-3.95, 1.9], "to": [3.95, 1.9], "thickness": 0.1, "height": 0.2, "restitution": 0.7},
                   {"type": "wall", "from": [0, -2], "to": [0, 0.6], "thickness": 0.1, "height": 0.2, "restitution": 0.7}
                 ]}
                """;
        try {
            return World.parse(json, "screened");
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    private static boolean holes(World w, double x, double y, Shot shot) {
        return new Simulator(w, SimulationSettings.DEFAULT).simulate(x, y, shot.vx(), shot.vy()).outcome() == Outcome.HOLED;
    }

    @Test
    void aPointInSightGetsAStraightPuttAndItHoles() {
        World w = screened();
        CountingSimulator sim = new CountingSimulator(w);
        OnePuttMap map = OnePuttMap.build(sim);
        assertEquals(OnePuttMap.RAYS, sim.count());
        assertTrue(map.marked(2, 0));
        assertEquals(0, map.cushions(2, 0));
        Shot putt = map.putt(2, 0);
        // Straight back at the hole: the direction from (2, 0) to (3, -1), within the cell's width.
        assertEquals(Math.atan2(-1, 1), Math.atan2(putt.vy(), putt.vx()), 0.06);
        // The energy guess on flat ground: v^2 = 2 g mu L.
        assertEquals(Math.sqrt(2 * 9.81 * 0.1 * Math.hypot(1, 1)), putt.speed(), 0.1);
        Stroke s = StagesTest.stroke(w, 2, 0);
        Attempt a = s.solveHole(putt, null);
        assertTrue(a.holed());
        assertTrue(holes(w, 2, 0, a.shot()));
    }

    @Test
    void aPointBehindTheWallGetsABankShotOffTheRimAndItHoles() {
        World w = screened();
        OnePuttMap map = OnePuttMap.build(new CountingSimulator(w));
        Stroke s = StagesTest.stroke(w, -2, -1);
        assertFalse(s.grid.clearLine(-2, -1, 3, -1, 0, 0), "the wall screens the hole");
        assertTrue(map.marked(-2, -1));
        assertEquals(1, map.cushions(-2, -1));
        Shot putt = map.putt(-2, -1);
        assertNotNull(putt);
        // Up towards the rim, over the wall's end.
        assertTrue(putt.vy() > 0 && putt.vx() > 0, putt.toString());
        Attempt a = s.solveBanked(putt);
        assertTrue(a.holed());
        assertTrue(holes(w, -2, -1, a.shot()));
    }
}
