package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Obstacle;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** The decorative trees round a course: deterministic, never on or near it, as many as asked. No GL. */
class TreePlacementTest {
    static final Bounds BOUNDS = new Bounds(-5, -3, 7, 4);

    @Test
    void theSameBoundsGiveTheSameTrees() {
        assertEquals(TreePlacement.around(BOUNDS, 40), TreePlacement.around(BOUNDS, 40));
        assertNotEquals(TreePlacement.around(BOUNDS, 40), TreePlacement.around(new Bounds(-5, -3, 7, 5), 40));
        assertNotEquals(TreePlacement.around(BOUNDS, 40, 1), TreePlacement.around(BOUNDS, 40, 2));
    }

    @Test
    void treesStandOutsideTheBoundsAndTheirMarginWithinReach() {
        for (long seed = 0; seed < 20; seed++) {
            List<Obstacle.Tree> trees = TreePlacement.around(BOUNDS, 48, seed);
            assertEquals(48, trees.size(), "seed " + seed);
            for (Obstacle.Tree t : trees) {
                double d = TreePlacement.distance(BOUNDS, t.position().x(), t.position().y());
                // The crown (the model reaches about its size from the trunk) stays 1.5 m clear of the course.
                double crown = 1.05 * TreePlacement.crownSize(t.height(), t.radius());
                assertTrue(d >= TreePlacement.MIN_DISTANCE && d - crown >= 1.4, "seed " + seed + ": a tree at " + t.position() + " reaches within " + (d - crown) + " m");
                assertTrue(d <= TreePlacement.MAX_DISTANCE, "seed " + seed + ": a tree " + d + " m away");
                assertTrue(t.height() >= TreePlacement.MIN_HEIGHT && t.height() <= TreePlacement.MAX_HEIGHT);
            }
        }
    }

    @Test
    void sizesAndDistancesVary() {
        List<Obstacle.Tree> trees = TreePlacement.around(BOUNDS, 48);
        double nearest = Double.MAX_VALUE, furthest = 0, low = Double.MAX_VALUE, high = 0;
        for (Obstacle.Tree t : trees) {
            double d = TreePlacement.distance(BOUNDS, t.position().x(), t.position().y());
            nearest = Math.min(nearest, d);
            furthest = Math.max(furthest, d);
            low = Math.min(low, t.height());
            high = Math.max(high, t.height());
        }
        assertTrue(nearest < 10 && furthest > 30, nearest + " to " + furthest + " m");
        assertTrue(high - low > 1, low + " to " + high + " m tall");
    }

    @Test
    void noneAskedNoneGiven() {
        assertTrue(TreePlacement.around(BOUNDS, 0).isEmpty());
    }
}
