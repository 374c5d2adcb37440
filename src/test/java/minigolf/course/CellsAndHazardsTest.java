package minigolf.course;

import static minigolf.course.CourseLoaderTest.BASE;
import static minigolf.course.CourseLoaderTest.SRC;
import static minigolf.course.CourseLoaderTest.edit;
import static minigolf.course.CourseLoaderTest.error;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The cells shape and the zone hazard (docs/course-format.md), as the classic tracks use them. */
class CellsAndHazardsTest {
    static final String RECT_ZONE = "{ \"shape\": { \"type\": \"rect\", \"min\": [1, -1], \"max\": [2, 1] }, \"kineticFriction\": 0.25, \"staticFriction\": 0.3 }";

    static String zone(String zone) {
        return edit(RECT_ZONE, zone);
    }

    static final String CELLS = "{ \"type\": \"cells\", \"origin\": [0, 0], \"size\": 0.5, \"columns\": 4, \"rows\": 3, "
            + "\"spans\": [[0, 1, 3], [2, 0, 1], [2, 3, 4]] }";

    @Test
    void cellsContainTheirSpans() throws Exception {
        Course c = CourseLoader.parse(zone("{ \"shape\": " + CELLS + ", \"kineticFriction\": 0.25, \"staticFriction\": 0.3 }"), SRC);
        Shape.Cells s = (Shape.Cells) c.zones().get(0).shape();
        assertTrue(s.contains(0.75, 0.25) && s.contains(1.25, 0.25));
        assertFalse(s.contains(0.25, 0.25) || s.contains(1.75, 0.25));
        assertTrue(s.contains(0.25, 1.25) && s.contains(1.75, 1.25));
        assertFalse(s.contains(0.75, 1.25) || s.contains(0.75, 0.75));
        assertFalse(s.contains(-0.1, 1.25) || s.contains(2.1, 1.25) || s.contains(0.25, 1.6));
    }

    @Test
    void cellsAndHazardsWriteAndReadBack() throws Exception {
        Shape.Cells cells = new Shape.Cells(new Vec2(-1, -2), 0.25, 7, 5, new int[]{0, 0, 7, 3, 2, 4, 4, 6, 7});
        Zone.Hazard acid = new Zone.Hazard(Zone.Hazard.Kind.ACID, Zone.Hazard.When.REST, Zone.Hazard.ReturnTo.COURSE_START, 0);
        Course base = CourseLoader.parse(BASE, SRC);
        Course c = new Course(base.format(), base.name(), base.terrain(), base.bounds(), base.physics(), base.start(),
                base.hole(), List.of(new Zone(cells, 0.1, 0.2, acid), new Zone(cells, 0.3, 0.3, Zone.Hazard.WATER)),
                base.obstacles());
        String json = CourseWriter.toJson(c);
        Course again = CourseLoader.parse(json, SRC);
        assertEquals(c.zones(), again.zones());
        assertEquals(json, CourseWriter.toJson(again));
    }

    @Test
    void hazardDefaultsAreTerrainWater() throws Exception {
        Course c = CourseLoader.parse(zone("{ \"shape\": " + CELLS + ", \"kineticFriction\": 0.25, \"staticFriction\": 0.3, \"hazard\": {} }"), SRC);
        assertEquals(Zone.Hazard.WATER, c.zones().get(0).hazard());
    }

    @Test
    void errors() {
        String z = "{ \"shape\": %s, \"kineticFriction\": 0.25, \"staticFriction\": 0.3%s }";
        assertEquals("courses/x.json: zones[0].shape.spans[1]: row 3 is outside 0..2",
                error(zone(z.formatted(CELLS.replace("[2, 0, 1]", "[3, 0, 1]"), ""))));
        assertEquals("courses/x.json: zones[0].shape.spans[0]: columns 3..1 must satisfy start < end <= 4",
                error(zone(z.formatted(CELLS.replace("[0, 1, 3]", "[0, 3, 1]"), ""))));
        assertEquals("courses/x.json: zones[0].shape.spans[2]: columns 3..5 must satisfy start < end <= 4",
                error(zone(z.formatted(CELLS.replace("[2, 3, 4]", "[2, 3, 5]"), ""))));
        assertEquals("courses/x.json: zones[0].shape.spans[0][0]: expected a whole number >= 0, got -1",
                error(zone(z.formatted(CELLS.replace("[0, 1, 3]", "[-1, 1, 3]"), ""))));
        assertEquals("courses/x.json: zones[0].shape.spans[0]: expected [row, start, end], got [0,1]",
                error(zone(z.formatted(CELLS.replace("[0, 1, 3]", "[0, 1]"), ""))));
        assertEquals("courses/x.json: zones[0].shape.columns: must be a whole number >= 1, got 0",
                error(zone(z.formatted(CELLS.replace("\"columns\": 4", "\"columns\": 0"), ""))));
        assertEquals("courses/x.json: zones[0].shape: too many cells: 2000 columns of 2000 rows = 4000000 (the limit is 1048576)",
                error(zone(z.formatted(CELLS.replace("\"columns\": 4", "\"columns\": 2000").replace("\"rows\": 3", "\"rows\": 2000"), ""))));
        assertEquals("courses/x.json: zones[0].hazard.kind: expected one of water, acid, got \"lava\"",
                error(zone(z.formatted(CELLS, ", \"hazard\": { \"kind\": \"lava\" }"))));
        assertEquals("courses/x.json: zones[0].hazard.when: expected one of enter, rest, got 3",
                error(zone(z.formatted(CELLS, ", \"hazard\": { \"when\": 3 }"))));
        assertEquals("courses/x.json: zones[0].hazard.returnTo: expected one of strokeStart, courseStart, got \"tee\"",
                error(zone(z.formatted(CELLS, ", \"hazard\": { \"returnTo\": \"tee\" }"))));
        assertEquals("courses/x.json: zones[0].hazard.penalty: must be 0 or 1, got 2",
                error(zone(z.formatted(CELLS, ", \"hazard\": { \"penalty\": 2 }"))));
        String unknown = error(zone(z.formatted(CELLS, ", \"hazard\": { \"depth\": 2 }")));
        assertTrue(unknown.startsWith("courses/x.json: zones[0].hazard"), unknown);
    }

    /** The start may not be in water that ends a stroke on entering; shallow water (at rest) is fine. */
    @Test
    void startInAHazard() throws Exception {
        String cover = "{ \"shape\": { \"type\": \"rect\", \"min\": [-4, -1], \"max\": [-2, 1] }, \"kineticFriction\": 0.25, \"staticFriction\": 0.3, \"hazard\": %s }";
        assertEquals("courses/x.json: start: (-3, 0) is in a water zone",
                error(edit(RECT_ZONE, cover.formatted("{ \"when\": \"enter\" }"))));
        CourseLoader.parse(edit(RECT_ZONE, cover.formatted("{ \"when\": \"rest\" }")), SRC);
    }
}
