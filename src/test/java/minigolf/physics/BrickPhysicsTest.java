package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Brick;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import org.junit.jupiter.api.Test;

/** Breakable bricks: each contact takes a hit, the last hit still bounces, then the brick is gone (docs/physics.md). */
public class BrickPhysicsTest {
    /** A flat lane, x from -1 to 9: the ball starts at 0, a brick across the lane at x 2..2.25, the hole at x 6. */
    public static Course lane(int hits) {
        return new Course(Course.FORMAT, "brick lane", new TerrainSpec.HeightExpression("0"), new Bounds(-1, -1, 9, 1),
                new PhysicsSettings(9.81, 0.1, 0.2, 5.0, minigolf.course.PhysicsModel.CLASSIC), new Vec2(0, 0), new Hole(new Vec2(6, 0), 0.1, HoleRule.REST, null),
                List.of(), List.of(), List.of(), List.of(), List.of(), "meadowbrook", List.of(),
                List.of(new Brick(new Vec3(2, -1, -0.5), new Vec3(2.25, 1, 0.5), hits, 0.9)));
    }

    @Test
    void aBrickTakesFourHitsAndTheFifthPuttPassesWhereTheFourBounced() {
        World world = World.of(lane(4));
        assertEquals(List.of(4), List.of(world.state().hitsLeft(0)));
        // Each putt at 2 m/s reaches the brick (it would roll 2^2 / (2 * 0.981) = 2.04 m) and comes back.
        for (int hit = 1; hit <= 4; hit++) {
            ShotResult r = new Simulator(world, SimulationSettings.DEFAULT).simulate(0, 0, 2, 0);
            assertEquals(Outcome.STOPPED, r.outcome());
            assertTrue(r.endX() < 2 - 0.0425, "putt " + hit + " bounced back off the brick: x " + r.endX());
            assertArrayEquals(new int[]{4 - hit}, r.state().hitsLeft(), "putt " + hit);
            world = world.withState(r.state());
        }
        assertEquals(false, world.state().standing(0));
        // The fifth: nothing stops it before the hole's row; it rolls its full 2.04 m (+-1 mm).
        ShotResult fifth = new Simulator(world, SimulationSettings.DEFAULT).simulate(0, 0, 2, 0);
        assertEquals(2 * 2 / (2 * 0.981), fifth.endX(), 0.001);
        assertSame(world.state(), fifth.state());
    }

    @Test
    void aBrickBrokenMidStrokeIsGoneForTheRestOfIt() {
        // One hit left: the fast putt bounces off it (the breaking hit bounces) and ...
        World world = World.of(lane(1));
        ShotResult r = new Simulator(world, SimulationSettings.DEFAULT).simulate(2.6, 0, -4, 0);
        // ... it rolls from x 2.6 left: a wall at x 2.25 sends it back right with 0.9 of its speed; as
        // the brick broke on that hit nothing stops it afterwards: it ends right of where it started.
        assertArrayEquals(new int[]{0}, r.state().hitsLeft());
        assertTrue(r.endX() > 2.6, "bounced right: x " + r.endX());
        // With the brick standing twice, the ball meets it only once on that path: same end, one hit left.
        ShotResult two = new Simulator(World.of(lane(2)), SimulationSettings.DEFAULT).simulate(2.6, 0, -4, 0);
        assertArrayEquals(new int[]{1}, two.state().hitsLeft());
        assertEquals(r.endX(), two.endX(), 1e-9);
    }

    @Test
    void theStateIsCheckedAgainstTheCourse() {
        Course c = lane(3);
        assertEquals("brick 0 takes 3 hits, the state says 4 left",
                org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                        () -> CourseState.of(c, new int[]{4})).getMessage());
        assertEquals("the course has 1 bricks, the state 2",
                org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                        () -> CourseState.of(c, new int[]{1, 1})).getMessage());
        assertEquals(CourseState.initial(c), CourseState.of(c, new int[]{3}));
    }
}
