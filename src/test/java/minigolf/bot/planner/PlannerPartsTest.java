package minigolf.bot.planner;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.bot.Shot;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The planner's small parts: first Jacobians, bank faces, the closest approach to the hole. */
class PlannerPartsTest {
    private static World course(String obstacles) {
        try {
            return World.parse("{\"format\":1,\"name\":\"t\",\"terrain\":{\"height\":\"0.1\"},\"bounds\":{\"min\":[-5,-3],"
                    + "\"max\":[5,3]},\"physics\":{\"kineticFriction\":0.1,\"staticFriction\":0.2,\"maxSpeed\":5},"
                    + "\"start\":[-3,0],\"hole\":{\"position\":[3,0],\"radius\":0.1},\"obstacles\":[" + obstacles + "]}", "t");
        } catch (minigolf.course.CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    @Test
    void theFlatJacobianMatchesTheEngineOnFlatGround() {
        // Along the shot: L = v^2 / (2 mu g), dL/dv = 2L/v; across: a turn moves the rest point by L da.
        World flat = course("");
        Simulator engine = new Simulator(flat, SimulationSettings.DEFAULT);
        double v = 3, h = 1e-4;
        double x0 = engine.simulate(-3, 0, v, 0).endX(), x1 = engine.simulate(-3, 0, v + h, 0).endX();
        double y1 = engine.simulate(-3, 0, v, h).endY();
        double[] j = Jacobians.flat(Shot.of(v, 0), x0 + 3, 0);
        assertEquals((x1 - x0) / h, j[0], 1e-3 * j[0]);
        assertEquals(y1 / h, j[3], 1e-3 * j[3]);
        assertEquals(0, j[1], 1e-12);
        assertEquals(0, j[2], 1e-12);
    }

    @Test
    void mirroringFlipsTheComponentAcrossTheLineAndTwiceIsTheIdentity() {
        double[] j = {1, 2, 3, 4};
        assertArrayEquals(new double[] {1, 2, -3, -4}, Jacobians.reflected(j, 0, 1), 1e-12);
        double n = Math.sqrt(0.5);
        assertArrayEquals(j, Jacobians.reflected(Jacobians.reflected(j, n, n), n, n), 1e-12);
    }

    @Test
    void aWallGivesItsTwoLongSidesMovedOutByTheBallsRadius() {
        World w = course("{\"type\":\"wall\",\"from\":[0,1],\"to\":[4,1],\"thickness\":0.1,\"height\":0.2,\"restitution\":0.6}");
        double r = w.physics().ballRadius();
        List<double[]> faces = BankFaces.of(w);
        assertEquals(2, faces.size());
        assertArrayEquals(new double[] {0, 1 + 0.05 + r, 4, 1 + 0.05 + r, 0, 1, 0.6}, faces.get(0), 1e-12);
        assertArrayEquals(new double[] {0, 1 - 0.05 - r, 4, 1 - 0.05 - r, 0, -1, 0.6}, faces.get(1), 1e-12);
    }

    @Test
    void aBoxGivesFourFacesUnlessTheBallRollsUnderIt() {
        assertEquals(4, BankFaces.of(course("{\"type\":\"box\",\"min\":[0,0,-1],\"max\":[1,2,1]}")).size());
        assertEquals(0, BankFaces.of(course("{\"type\":\"box\",\"min\":[0,0,0.5],\"max\":[1,2,1]}")).size());
    }

    @Test
    void theClosestApproachIsInterpolatedBetweenSteps() {
        // A ball along y = 0.05 passing a hole at the origin: nearest at (0, 0.05), between two steps.
        Approach a = new Approach(0, 0, -1, 0.05, Shot.of(2, 0));
        a.onStep(0.1, -0.3, 0.05, 1.8, 0);
        a.onStep(0.2, 0.2, 0.05, 1.6, 0);
        a.onStep(0.3, 0.6, 0.05, 1.4, 0);
        assertEquals(0, a.cx, 1e-12);
        assertEquals(0.05, a.cy, 1e-12);
        assertEquals(1.8 - 0.2 * 0.3 / 0.5, a.cvx, 1e-12);
        assertEquals(1, a.dirX, 1e-12);
        assertTrue(!a.collided);
    }
}
