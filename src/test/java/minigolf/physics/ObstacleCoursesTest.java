package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.SplittableRandom;
import minigolf.course.CourseException;
import minigolf.course.Obstacle;
import org.junit.jupiter.api.Test;

/** The example courses with obstacles do what their descriptions in courses/README.md promise. */
class ObstacleCoursesTest {
    private static World load(String name) throws CourseException {
        String dir = System.getProperty("minigolf.projectDir");
        Path root = Paths.get(dir != null ? dir : System.getProperty("user.dir"));
        return World.load(root.resolve("courses").resolve(name));
    }

    @Test
    void onlyAChipClearsTheWallOfChipOver() throws CourseException {
        World w = load("chip-wall.json");
        Simulator sim = TestWorlds.rk4(w);
        double sx = w.course().start().x(), sy = w.course().start().y(), max = w.physics().maxSpeed();
        for (int k = 0; k < 180; k++) {
            double a = 2 * Math.PI * k / 180;
            ShotResult r = sim.simulate(sx, sy, max * Math.cos(a), max * Math.sin(a));
            assertTrue(r.endX() < -1.2 || r.outcome() == Outcome.OUT, "a roll at " + k * 2 + " degrees passed: " + r);
        }
        ShotResult chip = sim.simulate(sx, sy, 3.4, 0.2, 3.4, null);
        assertTrue(chip.endX() > -1.2 && chip.outcome() == Outcome.STOPPED, chip.toString());
    }

    @Test
    void theWalledCourseKeepsEveryBallInside() throws CourseException {
        World w = load("walled.json");
        Simulator sim = TestWorlds.rk4(w);
        SplittableRandom random = new SplittableRandom(11);
        for (int k = 0; k < 500; k++) {
            double a = random.nextDouble() * 2 * Math.PI, v = w.physics().maxSpeed();
            ShotResult r = sim.simulate(-3, -2, v * Math.cos(a), v * Math.sin(a));
            assertTrue(Math.abs(r.endX()) < 3.85 && Math.abs(r.endY()) < 2.85, r.toString());
        }
    }

    @Test
    void theWindmillIsAFineMeshInTheWay() throws CourseException {
        World w = load("windmill.json");
        Obstacle.Model mill = (Obstacle.Model) w.course().obstacles().get(0);
        assertTrue(mill.mesh().triangleCount() >= 5000, mill.mesh().toString());
        ShotResult straight = TestWorlds.rk4(w).simulate(-4, 0, 4, 0, 0, null);
        StrokeEvent hit = straight.events().stream().filter(e -> e.type() == StrokeEvent.Type.COLLISION).findFirst().orElseThrow();
        // The tower's base has radius 0.45 (a 96-gon): the ball touches it about a radius before.
        assertEquals(-0.45 - 0.02135, hit.x(), 0.002);
    }

    @Test
    void theBenchmarkCourseHas200ObstaclesAndMoreThan5000Triangles() throws CourseException {
        World w = load("lake-obstacles.json");
        assertEquals(200, w.course().obstacles().size());
        assertTrue(w.obstacles().triangleCount() > 5000);
        assertEquals(load("lake.json").course().terrain(), w.course().terrain(), "the same terrain as the lake");
    }
}
