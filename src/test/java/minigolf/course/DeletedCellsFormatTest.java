package minigolf.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The grid's optional deletedCells field: loading, errors, and the writer's round trip. */
class DeletedCellsFormatTest {
    private static String course(String deleted, String start) {
        return "{ \"format\": 1, \"name\": \"d\", \"terrain\": { \"grid\": { \"origin\": [0, 0], \"spacing\": 1,"
                + " \"heights\": [[0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1]]" + deleted + " } },"
                + " \"bounds\": { \"min\": [0, 0], \"max\": [2, 2] },"
                + " \"physics\": { \"gravity\": 9.81, \"kineticFriction\": 0.1, \"staticFriction\": 0.2, \"maxSpeed\": 5, \"model\": \"classic\" },"
                + " \"start\": " + start + ", \"hole\": { \"position\": [1.5, 1.5], \"radius\": 0.1, \"rule\": \"rest\" } }";
    }

    private static String error(String deleted, String start) {
        return assertThrows(CourseException.class, () -> CourseLoader.parse(course(deleted, start), "d.json")).getMessage();
    }

    @Test
    void deletedCellsLoadAsAMask() throws CourseException {
        Course c = CourseLoader.parse(course(", \"deletedCells\": [[1, 0], [0, 1]]", "[0.5, 0.5]"), "d.json");
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) c.terrain();
        assertEquals(2, g.deletedCount());
        assertTrue(g.isDeleted(1, 0));
        assertTrue(g.isDeleted(0, 1));
        assertTrue(g.isDeletedAt(1.5, 0.5));
        assertEquals(false, g.isDeletedAt(0.5, 0.5));
        Course none = CourseLoader.parse(course("", "[0.5, 0.5]"), "d.json");
        assertNull(((TerrainSpec.HeightGrid) none.terrain()).deleted());
    }

    @Test
    void badDeletedCellsAreOneLineErrors() {
        assertEquals("d.json: terrain.grid.deletedCells[0][0]: cell index 2 is outside 0..1 (the grid has 2 cell columns)",
                error(", \"deletedCells\": [[2, 0]]", "[0.5, 0.5]"));
        assertEquals("d.json: terrain.grid.deletedCells[1]: cell [1, 0] is listed twice",
                error(", \"deletedCells\": [[1, 0], [1, 0]]", "[0.5, 0.5]"));
        assertEquals("d.json: terrain.grid.deletedCells[0]: expected [i, j] (two integers), got an array of 3",
                error(", \"deletedCells\": [[1, 0, 1]]", "[0.5, 0.5]"));
        assertEquals("d.json: terrain.grid.deletedCells[0][1]: expected an integer cell index, got a number",
                error(", \"deletedCells\": [[1, 0.5]]", "[0.5, 0.5]"));
        assertEquals("d.json: terrain.grid.deletedCells: expected an array of [i, j] cell indices, got a string",
                error(", \"deletedCells\": \"all\"", "[0.5, 0.5]"));
        assertEquals("d.json: start: (1.5, 0.5) is on a deleted terrain cell (out of bounds)",
                error(", \"deletedCells\": [[1, 0]]", "[1.5, 0.5]"));
    }

    @Test
    void theWriterRoundTripsDeletedCells() throws CourseException {
        Course c = CourseLoader.parse(course(", \"deletedCells\": [[0, 1], [1, 0]]", "[0.5, 0.5]"), "d.json");
        String json = CourseWriter.toJson(c);
        assertTrue(json.contains("\"deletedCells\": [\n        [1, 0], [0, 1]\n      ]"), json);
        assertEquals(c, CourseLoader.parse(json, "again.json"));
        // A course without deleted cells writes no field.
        Course none = CourseLoader.parse(course("", "[0.5, 0.5]"), "d.json");
        assertEquals(false, CourseWriter.toJson(none).contains("deletedCells"));
    }
}
