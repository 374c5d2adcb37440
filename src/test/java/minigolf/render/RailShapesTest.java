package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import minigolf.collision.ObstacleGeometry;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import org.junit.jupiter.api.Test;

/** A rail with a rounded top stays inside the slab the ball collides with, and its top is the slab's top. */
class RailShapesTest {
    @Test
    void theRoundedRailLiesInsideTheCollisionSlabAndReachesItsTop() {
        Obstacle.Wall w = new Obstacle.Wall(new Vec2(-1, 0.5), new Vec2(1, 1.5), 0.08, 0.1, 0.75);
        minigolf.course.HeightProbe ground = (x, y) -> 0.1 + 0.05 * x;
        List<double[]> v = new ArrayList<>();
        assertTrue(RailShapes.roundedWall(w, ground, (x, y, z, nx, ny, nz, shade) -> v.add(new double[]{x, y, z, nx, ny, nz, shade})));
        assertEquals(0, v.size() % 3);
        double[] slab = ObstacleGeometry.triangles(w, ground);
        double minZ = Double.POSITIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;
        for (int k = 2; k < slab.length; k += 3) {
            minZ = Math.min(minZ, slab[k]);
            maxZ = Math.max(maxZ, slab[k]);
        }
        double len = Math.hypot(2, 1), ux = 2 / len, uy = 1 / len;
        double highest = Double.NEGATIVE_INFINITY;
        for (double[] p : v) {
            double along = (p[0] + 1) * ux + (p[1] - 0.5) * uy, across = -(p[0] + 1) * uy + (p[1] - 0.5) * ux;
            assertTrue(along >= -0.04 - 1e-9 && along <= len + 0.04 + 1e-9, "along " + along);
            assertTrue(Math.abs(across) <= 0.04 + 1e-9, "across " + across);
            // The top line runs from h(from) + height to h(to) + height, as the slab's.
            double top = ground.height(-1, 0.5) + 0.1 + (ground.height(1, 1.5) - ground.height(-1, 0.5)) * (along + 0.04) / (len + 0.08);
            assertTrue(p[2] <= top + 1e-9 && p[2] >= minZ - 1e-9, "z " + p[2] + " top " + top);
            assertEquals(1, Math.sqrt(p[3] * p[3] + p[4] * p[4] + p[5] * p[5]), 1e-9, "unit normal");
            highest = Math.max(highest, p[2]);
        }
        assertEquals(maxZ, highest, 1e-9, "the crest reaches the slab's top");
        // Darker towards the foot: some vertices at each shade.
        assertTrue(v.stream().anyMatch(p -> p[6] == RailShapes.FOOTING_SHADE) && v.stream().anyMatch(p -> p[6] == RailShapes.GROUND_SHADE));
    }

    @Test
    void aFenceOfNoThicknessIsNotRounded() {
        Obstacle.Wall fence = new Obstacle.Wall(new Vec2(0, 0), new Vec2(1, 0), 0, 0.3, 0.7);
        assertFalse(RailShapes.roundedWall(fence, (x, y) -> 0, (x, y, z, nx, ny, nz, s) -> fail("no vertices")));
    }
}
