package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import minigolf.course.Course;
import minigolf.course.HoleRule;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import org.junit.jupiter.api.Test;

/** Every editing operation, with the numbers it must produce, and undo/redo of each. */
class EditorOperationsTest {
    /** 8 x 4 m, 0.1 m spacing: nodes 81 x 41, origin (-4, -2), flat at 0.1 m. */
    static CourseEditor flat() {
        return CourseEditor.create("test", 8, 4, 0.1, null);
    }

    @Test
    void aNewCourseIsAFlatGridCentredOnTheOrigin() {
        CourseEditor e = flat();
        EditableCourse c = e.course();
        assertEquals(81, c.columns());
        assertEquals(41, c.rows());
        assertEquals(-4, c.originX(), 1e-12);
        assertEquals(0.1, c.height(40, 20), 0);
        assertEquals(new Vec2(-2, 0), e.toCourse().start());
        assertEquals(new Vec2(2, 0), e.toCourse().hole().position());
        assertFalse(e.isDirty());
        assertFalse(e.canUndo());
    }

    @Test
    void aNewCourseFromAnExpressionSamplesItAtTheNodes() {
        CourseEditor e = CourseEditor.create("hills", 4, 2, 0.5, "0.2 + 0.1*x");
        EditableCourse c = e.course();
        assertEquals(9, c.columns());
        assertEquals(5, c.rows());
        for (int i = 0; i < 9; i++) assertEquals(0.2 + 0.1 * (-2 + 0.5 * i), c.height(i, 2), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> CourseEditor.create("x", 4, 2, 0.5, "0.2 +"));
        assertThrows(IllegalArgumentException.class, () -> CourseEditor.create("x", 400, 2, 0.5, null));
    }

    @Test
    void raiseAddsStrengthTimesTheFalloffAndUndoRestoresEveryBit() {
        CourseEditor e = flat();
        Course before = e.toCourse();
        e.brush(Brush.RAISE, 0, 0, 1.0, 0.2);
        EditableCourse c = e.course();
        assertEquals(0.3, c.height(40, 20), 1e-15);                        // centre: w = 1
        assertEquals(0.1 + 0.2 * 0.75 * 0.75, c.height(45, 20), 1e-12);   // d = 0.5 = r/2: w = (1 - 1/4)^2
        assertEquals(0.1, c.height(50, 20), 0);                            // d = r: untouched
        assertEquals(0.1, c.height(60, 20), 0);
        assertTrue(e.isDirty());
        assertEquals("raise brush", e.undoLabel());
        assertTrue(e.undo());
        assertEquals(before, e.toCourse());
        assertFalse(e.isDirty());
        assertTrue(e.redo());
        assertEquals(0.3, e.course().height(40, 20), 1e-15);
    }

    @Test
    void lowerBelowZeroMakesWaterThatThePhysicsSees() {
        CourseEditor e = flat();
        e.brush(Brush.LOWER, 0, 0, 1.0, 0.3);
        assertEquals(-0.2, e.course().height(40, 20), 1e-12);
        var r = new Simulator(e.world(), SimulationSettings.DEFAULT).simulate(-1.5, 0, 2, 0);
        assertEquals(Outcome.WATER, r.outcome());
    }

    @Test
    void aStrokeOfManyDabsIsOneUndoStep() {
        CourseEditor e = flat();
        Course before = e.toCourse();
        e.beginStroke(Brush.RAISE, -1, 0, 0.5, 0.05);
        for (int k = 1; k <= 20; k++) e.dab(-1 + 0.1 * k, 0);
        assertTrue(e.isStroking());
        e.endStroke();
        assertEquals(1, e.historySize());
        assertTrue(e.course().height(40, 20) > 0.1);
        e.undo();
        assertEquals(before, e.toCourse());
    }

    @Test
    void smoothMovesASpikeTowardsItsNeighbourhoodMean() {
        CourseEditor e = flat();
        e.setNodeHeight(40, 20, 1.0);
        // The spike's 3x3 mean is (1 + 8 * 0.1) / 9 = 0.2; strength 1 at the centre (w = 1) sets it there.
        e.brush(Brush.SMOOTH, 0, 0, 0.05, 1);
        assertEquals(0.2, e.course().height(40, 20), 1e-12);
        assertEquals(0.1, e.course().height(41, 20), 0); // outside the 0.05 m radius
        assertEquals(2, e.historySize());
    }

    @Test
    void flattenPullsTowardsTheHeightWhereTheStrokeBegan() {
        CourseEditor e = flat();
        e.brush(Brush.RAISE, 1, 0, 0.6, 0.5); // a hill at x = 1
        double top = e.course().height(50, 20);
        e.beginStroke(Brush.FLATTEN, 0, 0, 3, 1); // starts on flat ground (0.1)
        e.endStroke();
        assertEquals(0.1 + (top - 0.1) * (1 - Brush.weight(1, 3)), e.course().height(50, 20), 1e-12);
        assertEquals(0.1, e.course().height(40, 20), 0);
    }

    @Test
    void setNodeHeightChecksItsArguments() {
        CourseEditor e = flat();
        e.setNodeHeight(0, 0, -0.5);
        assertEquals(-0.5, e.course().height(0, 0), 0);
        assertEquals("set height", e.undoLabel());
        assertThrows(IllegalArgumentException.class, () -> e.setNodeHeight(81, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> e.setNodeHeight(0, 0, Double.NaN));
    }

    @Test
    void paintingSandChangesFrictionWhereThePhysicsReadsIt() {
        CourseEditor e = flat();
        Course before = e.toCourse();
        e.paint(1, 0, 0.5, Surface.SAND);
        EditableCourse c = e.course();
        assertEquals(0.45, c.kineticFriction(50, 20), 0);
        assertEquals(0.6, c.staticFriction(50, 20), 0);
        assertEquals(0.08, c.kineticFriction(40, 20), 0); // the course's own value elsewhere
        assertEquals(0.45, e.world().friction().kinetic(1, 0), 1e-12);
        TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) e.toCourse().terrain();
        assertEquals(0.08, g.kineticFriction()[0][0], 0);
        // Undo removes the friction grids again: the course is exactly as before.
        e.undo();
        assertEquals(before, e.toCourse());
        assertNull(((TerrainSpec.HeightGrid) e.toCourse().terrain()).kineticFriction());
        e.redo();
        assertEquals(0.45, e.course().kineticFriction(50, 20), 0);
        e.paint(1, 0, 0.2, 0.12, 0.25, "typed");
        assertEquals(0.12, e.course().kineticFriction(50, 20), 0);
        assertEquals(0.45, e.course().kineticFriction(54, 20), 0);
        assertThrows(IllegalArgumentException.class, () -> e.paint(0, 0, 1, -0.1, 0.2, "bad"));
    }

    @Test
    void deletingCellsPutsThemOutOfBoundsAndRestoringBringsThemBack() {
        CourseEditor e = flat();
        // Delete the whole column of cells at x in [0, 0.1]: a ball rolling along y = 0 goes out there.
        for (int j = 0; j < 40; j++) e.setCellDeleted(40, j, true);
        assertEquals(40, e.historySize());
        assertTrue(e.course().isDeleted(40, 7));
        var r = new Simulator(e.world(), SimulationSettings.DEFAULT).simulate(-2, 0, 3, 0);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(0.0, r.endX(), 1e-6);
        e.setCellDeleted(40, 20, false);
        assertFalse(e.course().isDeleted(40, 20));
        e.undo();
        assertTrue(e.course().isDeleted(40, 20));
        // Restoring within 0.25 m of the centre of cell (40, 20): its column's cells 18..22 (the neighbours were never deleted).
        assertEquals(5, e.setCellsDeleted(0.05, 0.05, 0.25, false));
        assertFalse(e.course().isDeleted(40, 18));
        assertTrue(e.course().isDeleted(40, 17));
        assertThrows(IllegalArgumentException.class, () -> e.setCellDeleted(80, 0, true));
    }

    @Test
    void obstaclesArePlacedMovedRotatedAndDeletedUpToTheMaximum() {
        CourseEditor e = flat();
        e.setMaxObstacles(2);
        Obstacle.Wall wall = new Obstacle.Wall(new Vec2(-1, 0), new Vec2(1, 0), 0.05, 0.2, 0.7);
        assertTrue(e.addObstacle(wall));
        assertTrue(e.addObstacle(new Obstacle.Tree(new Vec2(0, 1), 0.15, 1.5, 0.7)));
        assertFalse(e.addObstacle(new Obstacle.Tree(new Vec2(0, -1), 0.15, 1.5, 0.7)));
        assertEquals(2, e.course().obstacles().size());
        e.moveObstacle(0, 0.5, 1);
        Obstacle.Wall moved = (Obstacle.Wall) e.course().obstacles().get(0);
        assertEquals(new Vec2(-0.5, 1), moved.from());
        assertEquals(new Vec2(1.5, 1), moved.to());
        e.rotateObstacle(0, 90);
        Obstacle.Wall turned = (Obstacle.Wall) e.course().obstacles().get(0);
        assertEquals(0.5, turned.from().x(), 1e-12);
        assertEquals(0, turned.from().y(), 1e-12);
        assertEquals(0.5, turned.to().x(), 1e-12);
        assertEquals(2, turned.to().y(), 1e-12);
        assertEquals(1, e.obstacleNear(0.1, 1, 0.2)); // the tree at (0, 1)
        assertEquals(0, e.obstacleNear(0.55, 0.5, 0.2)); // on the turned wall
        assertEquals(-1, e.obstacleNear(3, -1.5, 0.2));
        e.removeObstacle(1);
        assertEquals(1, e.course().obstacles().size());
        e.undo();
        e.undo();
        e.undo();
        assertEquals(List.of(wall, new Obstacle.Tree(new Vec2(0, 1), 0.15, 1.5, 0.7)), e.course().obstacles());
        Obstacle.Box box = new Obstacle.Box(new Vec3(0, 0, 0), new Vec3(1, 1, 0.5), 350, 0.7);
        assertEquals(20, ((Obstacle.Box) ObstacleTools.rotated(box, 30)).rotationDeg(), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> e.moveObstacle(5, 0, 0));
    }

    @Test
    void startHoleAndPhysicsAreUndoable() {
        CourseEditor e = flat();
        Course before = e.toCourse();
        e.setStart(-3, 1);
        e.setHole(3, -1);
        e.setHoleRadius(0.15);
        e.setHoleRule(HoleRule.CAPTURE);
        PhysicsSettings p = new PhysicsSettings(9.81, 0.12, 0.3, 4, PhysicsModel.COMPLETE);
        e.setPhysics(p);
        e.setName("renamed");
        Course after = e.toCourse();
        assertEquals(new Vec2(-3, 1), after.start());
        assertEquals(new Vec2(3, -1), after.hole().position());
        assertEquals(0.15, after.hole().radius(), 0);
        assertEquals(HoleRule.CAPTURE, after.hole().rule());
        assertEquals(p, after.physics());
        assertEquals("renamed", after.name());
        assertThrows(IllegalArgumentException.class, () -> e.setStart(5, 0));
        assertThrows(IllegalArgumentException.class, () -> e.setHoleRadius(0));
        for (int k = 0; k < 6; k++) assertTrue(e.undo());
        assertFalse(e.undo());
        assertEquals(before, e.toCourse());
        for (int k = 0; k < 6; k++) assertTrue(e.redo());
        assertEquals(after, e.toCourse());
    }

    @Test
    void aRandomSequenceUndoneAndRedoneReturnsExactlyToEachState() {
        CourseEditor e = flat();
        Random rnd = new Random(7);
        Course[] states = new Course[41];
        states[0] = e.toCourse();
        for (int k = 1; k <= 40; k++) {
            double x = -3.5 + 7 * rnd.nextDouble(), y = -1.5 + 3 * rnd.nextDouble();
            switch (rnd.nextInt(6)) {
                case 0 -> e.brush(Brush.values()[rnd.nextInt(4)], x, y, 0.2 + rnd.nextDouble(), rnd.nextDouble() * 0.3);
                case 1 -> e.paint(x, y, 0.5, rnd.nextBoolean() ? Surface.SAND : Surface.GRASS);
                case 2 -> e.setCellsDeleted(x, y, 0.2, rnd.nextBoolean());
                case 3 -> e.addObstacle(new Obstacle.Tree(new Vec2(x, y), 0.1, 1, 0.7));
                case 4 -> e.setNodeHeight(rnd.nextInt(81), rnd.nextInt(41), rnd.nextDouble());
                default -> e.setStart(x, y);
            }
            states[e.historySize()] = e.toCourse();
        }
        int n = e.historySize();
        assertTrue(n >= 35, "most operations change something: " + n);
        for (int k = n - 1; k >= 0; k--) {
            e.undo();
            assertEquals(states[k], e.toCourse(), "after undoing to step " + k);
        }
        assertFalse(e.isDirty());
        for (int k = 1; k <= n; k++) {
            e.redo();
            assertEquals(states[k], e.toCourse(), "after redoing step " + k);
        }
        // A new edit after undo clears the redo stack.
        e.undo();
        e.setNodeHeight(0, 0, 2);
        assertFalse(e.canRedo());
        assertNotEquals(states[n], e.toCourse());
    }

    @Test
    void changesTellTheRendererWhatToRebuild() {
        CourseEditor e = flat();
        e.takeChanges();
        e.brush(Brush.RAISE, 0, 0, 0.25, 0.1);
        ChangeSet c = e.takeChanges();
        assertTrue(c.hasNodes());
        int[] range = c.nodeRange();
        assertEquals(38, range[0]); // nodes within 0.25 m of x = 0 (exclusive): -0.2 .. 0.2
        assertEquals(42, range[2]);
        assertFalse(c.structureChanged());
        assertTrue(e.takeChanges().isEmpty());
        e.addObstacle(new Obstacle.Tree(new Vec2(0, 1), 0.1, 1, 0.7));
        assertTrue(e.takeChanges().obstaclesChanged());
        e.setCellDeleted(0, 0, true);
        assertTrue(e.takeChanges().structureChanged());
    }
}
