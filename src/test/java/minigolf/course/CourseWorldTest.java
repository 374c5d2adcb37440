package minigolf.course;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The course file's optional "world": a bundled world's id, Meadowbrook when absent, written back only when set. */
class CourseWorldTest {
    static final String SRC = "courses/x.json";

    @Test
    void aCourseWithoutAWorldIsInMeadowbrookAndIsWrittenBackWithoutOne() throws Exception {
        Course c = CourseLoader.parse(CourseLoaderTest.BASE, SRC);
        assertEquals("meadowbrook", c.world());
        assertFalse(CourseWriter.toJson(c).contains("\"world\""));
    }

    @Test
    void aWorldIsReadWrittenAndReadBackEqual() throws Exception {
        String json = CourseLoaderTest.edit("\"name\": \"Lake\",", "\"name\": \"Lake\",\n  \"world\": \"canyon\",");
        Course c = CourseLoader.parse(json, SRC);
        assertEquals("canyon", c.world());
        String written = CourseWriter.toJson(c);
        assertTrue(written.contains("  \"world\": \"canyon\",\n"), written);
        assertEquals(c, CourseLoader.parse(written, SRC));
        assertEquals("winter", c.withWorld("winter").world());
        assertEquals("canyon", c.withObstacles(java.util.List.of()).world(), "copies keep the world");
        assertEquals("canyon", c.withPhysics(c.physics()).world());
    }

    @Test
    void anUnknownWorldOrAWrongTypeIsAOneLineError() {
        CourseException unknown = assertThrows(CourseException.class, () -> CourseLoader.parse(
                CourseLoaderTest.edit("\"name\": \"Lake\",", "\"name\": \"Lake\", \"world\": \"moon\","), SRC));
        assertEquals("courses/x.json: world: expected one of meadowbrook, seaside, canyon, winter, got \"moon\"", unknown.getMessage());
        CourseException number = assertThrows(CourseException.class, () -> CourseLoader.parse(
                CourseLoaderTest.edit("\"name\": \"Lake\",", "\"name\": \"Lake\", \"world\": 3,"), SRC));
        assertEquals("courses/x.json: world: expected a string, got a number", number.getMessage());
    }
}
