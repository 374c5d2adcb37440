package minigolf.course;

import static minigolf.course.CourseLoaderTest.BASE;
import static minigolf.course.CourseLoaderTest.edit;
import static minigolf.course.CourseLoaderTest.error;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The course field {@code bricks}: breakable bricks (docs/course-format.md, "Breakable bricks"). */
class BricksFormatTest {
    private static final String HOLE_LINE = "  \"hole\": { \"position\": [4, 1], \"radius\": 0.15, \"rule\": \"rest\" },";

    private static String withBricks(String bricks) {
        return edit(HOLE_LINE, HOLE_LINE + "\n  \"bricks\": " + bricks + ",");
    }

    @Test
    void readsWritesAndRoundTripsExactly() throws CourseException {
        Course c = CourseLoader.parse(withBricks("[ { \"min\": [0, -1, -1], \"max\": [0.25, 1, 1], \"hits\": 4 }, "
                + "{ \"min\": [1, 2, 0], \"max\": [1.5, 2.5, 0.3], \"hits\": 2, \"restitution\": 0.5 } ]"), "x");
        assertEquals(List.of(new Brick(new Vec3(0, -1, -1), new Vec3(0.25, 1, 1), 4, 0.9),
                new Brick(new Vec3(1, 2, 0), new Vec3(1.5, 2.5, 0.3), 2, 0.5)), c.bricks());
        String json = CourseWriter.toJson(c);
        assertTrue(json.contains("\"bricks\": [\n    { \"min\": [0, -1, -1], \"max\": [0.25, 1, 1], \"hits\": 4 },\n"
                + "    { \"min\": [1, 2, 0], \"max\": [1.5, 2.5, 0.3], \"hits\": 2, \"restitution\": 0.5 }\n  ],"), json);
        Course back = CourseLoader.parse(json, "round-trip");
        assertEquals(c, back);
        assertEquals(json, CourseWriter.toJson(back));
        // Kept through the course's other copies.
        assertEquals(c.bricks(), c.withWorld("seaside").withObstacles(List.of()).withHoles(c.hole(), List.of()).bricks());
    }

    /** What the renderer draws: the course's obstacles, then the bricks still standing as boxes. */
    @Test
    void theObstaclesDrawnAreTheStandingBricks() throws CourseException {
        Course c = CourseLoader.parse(withBricks("[ { \"min\": [0, -1, -1], \"max\": [0.25, 1, 1], \"hits\": 4 }, "
                + "{ \"min\": [1, 2, 0], \"max\": [1.5, 2.5, 0.3], \"hits\": 2 } ]"), "x");
        assertEquals(List.of(c.bricks().get(0).box(), c.bricks().get(1).box()), c.obstaclesWithBricks(i -> true));
        assertEquals(List.of(c.bricks().get(1).box()), c.obstaclesWithBricks(i -> i == 1));
        assertEquals(List.of(), c.obstaclesWithBricks(i -> false));
        Course base = CourseLoader.parse(BASE, "x");
        assertTrue(base.obstaclesWithBricks(i -> true) == base.obstacles());
    }

    @Test
    void aCourseWithoutBricksWritesNoField() throws CourseException {
        Course c = CourseLoader.parse(BASE, "x");
        assertEquals(List.of(), c.bricks());
        assertFalse(CourseWriter.toJson(c).contains("bricks"));
    }

    @Test
    void badBricksGiveOneLine() {
        assertEquals("courses/x.json: bricks: expected an array, got an object", error(withBricks("{}")));
        assertEquals("courses/x.json: bricks[0].hits: expected a whole number from 1 to 100, got 0",
                error(withBricks("[ { \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"hits\": 0 } ]")));
        assertEquals("courses/x.json: bricks[0].hits: expected a whole number from 1 to 100, got 2.5",
                error(withBricks("[ { \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"hits\": 2.5 } ]")));
        assertEquals("courses/x.json: bricks[0].hits: missing required field",
                error(withBricks("[ { \"min\": [0, 0, 0], \"max\": [1, 1, 1] } ]")));
        assertEquals("courses/x.json: bricks[0]: min must be < max in all three axes, got min (1, 0, 0), max (1, 1, 1)",
                error(withBricks("[ { \"min\": [1, 0, 0], \"max\": [1, 1, 1], \"hits\": 1 } ]")));
        assertEquals("courses/x.json: bricks[0].restitution: must be between 0 and 1, got 1.5",
                error(withBricks("[ { \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"hits\": 1, \"restitution\": 1.5 } ]")));
        assertEquals("courses/x.json: bricks[0].colour: unknown field (known: min, max, hits, restitution)",
                error(withBricks("[ { \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"hits\": 1, \"colour\": 3 } ]")));
        assertEquals("courses/x.json: bricks[0]: stands on the start at (-3, 0)",
                error(withBricks("[ { \"min\": [-3.5, -0.5, -1], \"max\": [-2.5, 0.5, 1], \"hits\": 1 } ]")));
        assertEquals("courses/x.json: bricks[0]: stands on the hole at (4, 1)",
                error(withBricks("[ { \"min\": [3.5, 0.5, -1], \"max\": [4.5, 1.5, 1], \"hits\": 1 } ]")));
        StringBuilder many = new StringBuilder("[");
        for (int i = 0; i <= Limits.BRICKS; i++) many.append(i > 0 ? ", " : "").append("{ \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"hits\": 1 }");
        assertEquals("courses/x.json: bricks: too many bricks: 2501 (the limit is 2500)", error(withBricks(many + "]")));
    }
}
