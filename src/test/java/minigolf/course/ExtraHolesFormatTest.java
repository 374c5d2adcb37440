package minigolf.course;

import static minigolf.course.CourseLoaderTest.BASE;
import static minigolf.course.CourseLoaderTest.edit;
import static minigolf.course.CourseLoaderTest.error;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/** The course field {@code extraHoles}: holes beside the main one (docs/course-format.md). */
class ExtraHolesFormatTest {
    private static final String HOLE_LINE = "  \"hole\": { \"position\": [4, 1], \"radius\": 0.15, \"rule\": \"rest\" },";

    private static String withExtra(String extra) {
        return edit(HOLE_LINE, HOLE_LINE + "\n  \"extraHoles\": " + extra + ",");
    }

    @Test
    void readsWritesAndRoundTripsExactly() throws CourseException {
        Course c = CourseLoader.parse(withExtra("[ { \"position\": [-1, 3], \"radius\": 0.1, \"rule\": \"capture\", "
                + "\"captureSpeed\": 0.7 }, { \"position\": [2, -4], \"radius\": 0.2 } ]"), "x");
        assertEquals(List.of(new Hole(new Vec2(-1, 3), 0.1, HoleRule.CAPTURE, 0.7),
                new Hole(new Vec2(2, -4), 0.2, HoleRule.REST, null)), c.extraHoles());
        assertEquals(3, c.holes().size());
        assertEquals(c.hole(), c.holes().get(0));
        String json = CourseWriter.toJson(c);
        assertTrue(json.contains("\"extraHoles\": [\n    { \"position\": [-1, 3], \"radius\": 0.1, \"rule\": \"capture\", "
                + "\"captureSpeed\": 0.7 },\n    { \"position\": [2, -4], \"radius\": 0.2, \"rule\": \"rest\" }\n  ],"), json);
        assertTrue(json.indexOf("\"extraHoles\"") > json.indexOf("\"hole\""), json);
        Course back = CourseLoader.parse(json, "round-trip");
        assertEquals(c, back);
        assertEquals(json, CourseWriter.toJson(back));
    }

    @Test
    void aOneHoleCourseWritesNoField() throws CourseException {
        Course c = CourseLoader.parse(BASE, "x");
        assertEquals(List.of(), c.extraHoles());
        assertFalse(CourseWriter.toJson(c).contains("extraHoles"));
        assertEquals(List.of(c.hole()), c.holes());
    }

    @Test
    void badExtraHolesGiveOneLine() {
        assertEquals("courses/x.json: extraHoles: expected an array, got an object", error(withExtra("{}")));
        assertEquals("courses/x.json: extraHoles[1].radius: must be > 0, got -0.1",
                error(withExtra("[ { \"position\": [0, 3], \"radius\": 0.1 }, { \"position\": [1, 3], \"radius\": -0.1 } ]")));
        assertEquals("courses/x.json: extraHoles[0].rule: expected one of rest, capture, got \"cup\"",
                error(withExtra("[ { \"position\": [0, 3], \"radius\": 0.1, \"rule\": \"cup\" } ]")));
        assertEquals("courses/x.json: extraHoles[0].position: (7, 3) is outside the bounds",
                error(withExtra("[ { \"position\": [7, 3], \"radius\": 0.1 } ]")));
        StringBuilder many = new StringBuilder("[");
        for (int i = 0; i <= Limits.EXTRA_HOLES; i++) many.append(i > 0 ? ", " : "").append("{ \"position\": [0, 3], \"radius\": 0.1 }");
        assertEquals("courses/x.json: extraHoles: too many holes: 101 (the limit is 100)", error(withExtra(many + "]")));
    }

    @Test
    void anExtraHoleInWaterIsRefused() {
        Function<TerrainSpec, HeightProbe> probes = spec -> (x, y) -> y > 2 ? -0.5 : 1.0;
        assertEquals("courses/x.json: extraHoles[0].position: (0, 3) is in water (h = -0.5)",
                error(withExtra("[ { \"position\": [0, 3], \"radius\": 0.1 } ]"), probes));
    }
}
