package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import org.junit.jupiter.api.Test;

/** The ground's ambient occlusion: dark at the foot of what stands on it, open further away. */
class OcclusionMapTest {
    static final Bounds B = new Bounds(-2, -1, 2, 1);
    static final Obstacle.Wall WALL = new Obstacle.Wall(new Vec2(-1, 0), new Vec2(1, 0), 0.08, 0.1, 0.75);

    @Test
    void theGroundDarkensTowardsAWallsFootAndIsOpenBeyondItsReach() {
        OcclusionMap m = OcclusionMap.of(B, List.of(WALL), (x, y) -> 0.1);
        double foot = m.at(0, 0.05), mid = m.at(0, 0.04 + OcclusionMap.REACH / 2), open = m.at(0, 0.04 + OcclusionMap.REACH + 0.05);
        assertTrue(foot < 1 - 0.8 * OcclusionMap.STRENGTH, "at the foot " + foot);
        assertTrue(foot < mid && mid < open, foot + " < " + mid + " < " + open);
        assertEquals(1, open, 1e-6);
        assertEquals(1, m.at(1.8, 0.8), 1e-6, "far from everything");
        assertEquals(m.at(0, 0.11), m.at(0, -0.11), 1e-6, "both sides alike (texel centres 0.11 m either side)");
    }

    @Test
    void aCornerIsDarkerThanAStraightRailAndALowBoxDarkensLess() {
        Obstacle.Wall across = new Obstacle.Wall(new Vec2(1, 0), new Vec2(1, 0.8), 0.08, 0.1, 0.75);
        OcclusionMap m = OcclusionMap.of(B, List.of(WALL, across), (x, y) -> 0.1);
        assertTrue(m.at(0.92, 0.09) < m.at(0, 0.09) - 0.05, "corner " + m.at(0.92, 0.09) + " straight " + m.at(0, 0.09));
        Obstacle.Box low = new Obstacle.Box(new Vec3(-0.2, -0.2, 0.05), new Vec3(0.2, 0.2, 0.125), 0, 0.8);
        Obstacle.Box tall = new Obstacle.Box(new Vec3(-0.2, -0.2, 0.05), new Vec3(0.2, 0.2, 0.4), 0, 0.8);
        double nearLow = OcclusionMap.of(B, List.of(low), (x, y) -> 0.1).at(0.25, 0);
        double nearTall = OcclusionMap.of(B, List.of(tall), (x, y) -> 0.1).at(0.25, 0);
        assertTrue(nearTall < nearLow && nearLow < 1, nearTall + " < " + nearLow);
        Obstacle.Box floating = new Obstacle.Box(new Vec3(-0.2, -0.2, 0.5), new Vec3(0.2, 0.2, 0.8), 0, 0.8);
        assertEquals(1, OcclusionMap.of(B, List.of(floating), (x, y) -> 0.1).at(0.25, 0), 1e-6, "a box in the air");
    }

    @Test
    void theMapHasAboutTwoCentimetreTexelsAndBytesOfTheSameSize() {
        OcclusionMap m = OcclusionMap.of(B, List.of(WALL), (x, y) -> 0.1);
        assertEquals(200, m.width());
        assertEquals(100, m.height());
        assertEquals(200 * 100, m.bytes().length);
        assertEquals((byte) 255, m.bytes()[0]);
    }
}
