package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseLoader;
import minigolf.course.Obstacle;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Validation, saving, opening and the recovery file. */
class EditorFilesTest {
    @TempDir
    Path dir;

    @Test
    void aValidCourseHasNoProblems() {
        assertEquals(List.of(), EditorOperationsTest.flat().validate());
    }

    @Test
    void startInWaterIsReportedWhereItIs() {
        CourseEditor e = EditorOperationsTest.flat();
        e.brush(Brush.LOWER, -2, 0, 0.5, 0.4);
        List<Problem> problems = e.validate();
        assertEquals(1, problems.size());
        assertEquals("start: (-2.00, 0.00) is in water (h = -0.300)", problems.get(0).message());
        assertEquals(-2, problems.get(0).x(), 0);
        assertEquals(0, problems.get(0).y(), 0);
    }

    @Test
    void holeOnADeletedCellAndStartUnderATreeAreReported() {
        CourseEditor e = EditorOperationsTest.flat();
        e.setCellsDeleted(2, 0, 0.2, true);
        e.addObstacle(new Obstacle.Tree(new Vec2(-2, 0.05), 0.1, 1, 0.7));
        List<String> messages = e.validate().stream().map(Problem::message).toList();
        assertEquals(List.of("start: (-2.00, 0.00) is covered by an obstacle", "hole: (2.00, 0.00) is on a deleted cell"),
                messages);
    }

    @Test
    void aHoleWalledInIsUnreachableAndAGapMakesItReachable() {
        CourseEditor e = EditorOperationsTest.flat();
        // A fence across the whole course at x = 0 (thin walls: the sweep between cell centres finds them).
        e.addObstacle(new Obstacle.Wall(new Vec2(0.01, -2.5), new Vec2(0.01, 0.3), 0, 0.2, 0.7));
        e.addObstacle(new Obstacle.Wall(new Vec2(0.01, 0.7), new Vec2(0.01, 2.5), 0, 0.2, 0.7));
        assertEquals(List.of(), e.validate(), "a 0.4 m gap at y in [0.3, 0.7]");
        int[][] path = Reachability.path(e.course(), e.world());
        boolean throughGap = false;
        for (int[] cell : path) {
            double y = Reachability.centerY(e.course(), cell[1]);
            if (cell[0] == 40 && y > 0.3 && y < 0.7) throughGap = true;
        }
        assertTrue(throughGap, "the path goes through the gap");
        e.addObstacle(new Obstacle.Wall(new Vec2(0.01, 0.2), new Vec2(0.01, 0.8), 0, 0.2, 0.7));
        List<Problem> problems = e.validate();
        assertEquals(1, problems.size());
        assertEquals("hole: no way from the start to the hole (A* on the course grid)", problems.get(0).message());
        assertEquals(2, problems.get(0).x(), 0);
        // A moat of water does the same; undoing the wall and the moat clears it.
        e.undo();
        e.brush(Brush.LOWER, 2, 0, 1.2, 0.5);
        e.setHole(2, 0);
        assertTrue(e.validate().stream().anyMatch(p -> p.message().startsWith("hole: (2.00, 0.00) is in water")));
    }

    @Test
    void aRingOfDeletedCellsCutsTheHoleOff() {
        CourseEditor e = EditorOperationsTest.flat();
        EditableCourse c = e.course();
        for (int j = 0; j < c.rows() - 1; j++) e.setCellDeleted(45, j, true); // x in [0.5, 0.6]
        assertEquals("hole: no way from the start to the hole (A* on the course grid)", e.validate().get(0).message());
        e.setCellDeleted(45, 0, false); // a one-cell gap at the edge
        assertEquals(List.of(), e.validate());
    }

    @Test
    void saveWritesALoadableCourseAndMarksItClean() throws Exception {
        CourseEditor e = EditorOperationsTest.flat();
        e.brush(Brush.RAISE, 0, 1, 0.8, 0.3);
        e.paint(-1, -1, 0.4, Surface.SAND);
        e.setCellsDeleted(3.5, 1.5, 0.3, true);
        e.addObstacle(new Obstacle.Wall(new Vec2(-1, 1), new Vec2(1, 1.5), 0.05, 0.2, 0.7));
        Path file = dir.resolve("mine.json");
        assertThrows(CourseException.class, e::save, "a new course has no file yet");
        e.saveAs(file);
        assertFalse(e.isDirty());
        assertEquals(file, e.file());
        Course loaded = World.load(file).course();
        assertEquals(e.toCourse(), loaded);
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) loaded.terrain();
        assertEquals(0.4, g.heights()[30][40], 1e-12);
        assertTrue(g.deletedCount() > 0);
        // Opening the saved file gives the same course again, clean.
        CourseEditor again = CourseEditor.open(file);
        assertEquals(loaded, again.toCourse());
        assertFalse(again.isDirty());
        // Undo back to the saved point is clean again; one more undo is not.
        e.setNodeHeight(0, 0, 1);
        assertTrue(e.isDirty());
        e.undo();
        assertFalse(e.isDirty());
        e.undo();
        assertTrue(e.isDirty());
    }

    @Test
    void aCourseWithProblemsIsNotSavedAndThePreviousFileStays() throws Exception {
        CourseEditor e = EditorOperationsTest.flat();
        Path file = dir.resolve("mine.json");
        e.saveAs(file);
        String before = Files.readString(file, StandardCharsets.UTF_8);
        e.brush(Brush.LOWER, 2, 0, 0.5, 0.5);
        CourseException x = assertThrows(CourseException.class, e::save);
        assertEquals(file + ": cannot save: hole: (2.00, 0.00) is in water (h = -0.400)", x.getMessage());
        assertEquals(before, Files.readString(file, StandardCharsets.UTF_8));
        assertTrue(e.isDirty());
        assertEquals(List.of("mine.json"), Files.list(dir).map(p -> p.getFileName().toString()).toList());
    }

    @Test
    void anExpressionCourseOpensAsASampledGridThatMustBeSavedAs() throws Exception {
        Path file = Path.of("courses/sine-hills.json");
        Course original = CourseLoader.load(file);
        CourseEditor e = CourseEditor.open(file);
        assertNull(e.file(), "saving must not overwrite the expression course");
        EditableCourse c = e.course();
        assertEquals(original.bounds().minX(), c.originX(), 0);
        World expr = World.of(original);
        for (int j = 0; j < c.rows(); j += 7) {
            for (int i = 0; i < c.columns(); i += 7) {
                assertEquals(expr.terrain().height(c.nodeX(i), c.nodeY(j)), c.height(i, j), 1e-12);
            }
        }
        assertEquals(original.obstacles(), e.toCourse().obstacles());
    }

    @Test
    void theRecoveryFileBringsBackUnsavedWork() throws Exception {
        Recovery recovery = new Recovery(dir.resolve("config"));
        assertFalse(recovery.exists());
        CourseEditor e = EditorOperationsTest.flat();
        Path file = dir.resolve("mine.json");
        e.saveAs(file);
        assertFalse(recovery.autosave(e, 100), "nothing unsaved");
        e.brush(Brush.RAISE, 0, 0, 1, 0.25);
        assertTrue(recovery.autosave(e, 100));
        assertFalse(recovery.autosave(e, 105), "within the interval");
        e.setNodeHeight(1, 1, 0.7);
        assertFalse(recovery.autosave(e, 105));
        assertTrue(recovery.autosave(e, 100 + Recovery.INTERVAL_SECONDS));
        // The editor "crashes" here: the next start finds the recovery file.
        Recovery next = new Recovery(dir.resolve("config"));
        assertTrue(next.exists());
        Recovery.Recovered r = next.load();
        assertEquals(file.toAbsolutePath(), r.originalFile());
        CourseEditor restored = CourseEditor.recovered(r);
        assertEquals(e.toCourse(), restored.toCourse());
        assertTrue(restored.isDirty());
        next.clear();
        assertFalse(next.exists());
        // A broken recovery file is a one-line error, not a crash.
        Files.createDirectories(dir.resolve("config"));
        Files.writeString(next.file(), "{ broken");
        CourseException x = assertThrows(CourseException.class, next::load);
        assertTrue(x.getMessage().startsWith(next.file().toString()) || x.getMessage().contains("JSON"), x.getMessage());
    }
}
