package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.Obstacle;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** The tile-course generator: seeded, loadable, the start on the left and the hole on the right inside a rim. */
class TileCoursesTest {
    @Test
    void theSameSeedGivesTheSameCoursesAndEveryOneLoads() {
        assertEquals(TileCourses.json(new java.util.SplittableRandom(9), "t"), TileCourses.json(new java.util.SplittableRandom(9), "t"));
        assertTrue(!TileCourses.json(new java.util.SplittableRandom(9), "t").equals(TileCourses.json(new java.util.SplittableRandom(10), "t")));
        List<World> a = TileCourses.generate(5, 6);
        assertEquals(6, a.size());
        for (int i = 0; i < a.size(); i++) {
            World w = a.get(i);
            assertTrue(w.course().start().x() < TileCourses.TILE, "start in the first column");
            assertTrue(w.course().hole().position().x() > (TileCourses.COLS - 1) * TileCourses.TILE, "hole in the last");
            // The rim and at least the walls of a maze over 24 tiles (a spanning tree leaves 38 - 23 - extra edges).
            long walls = w.course().obstacles().stream().filter(o -> o instanceof Obstacle.Wall).count();
            assertTrue(walls >= 4 + 8, "walls: " + walls);
            assertTrue(w.terrain().height(w.course().start().x(), w.course().start().y()) > 0, "start dry");
        }
    }
}
