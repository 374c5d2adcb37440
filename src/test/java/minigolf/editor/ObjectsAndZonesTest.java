package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.course.Shape;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.course.Zone;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Placing .obj models, editing object sizes and restitution, and friction zones: undo/redo and save/load. */
class ObjectsAndZonesTest {
    @TempDir
    Path dir;

    @Test
    void everyBundledModelLoadsFromTheGameResources() {
        for (String file : ModelCatalog.BUNDLED) assertTrue(ModelCatalog.load(file).triangleCount() > 0, file);
        // The windmill (courses/models/windmill.obj) reaches 0.4738 m from its axis and 2.2238 m up.
        float[] p = ModelCatalog.load("models/windmill.obj").positions();
        double maxX = 0, maxZ = 0;
        for (int k = 0; k < p.length; k += 3) {
            maxX = Math.max(maxX, p[k]);
            maxZ = Math.max(maxZ, p[k + 2]);
        }
        assertEquals(0.473762, maxX, 1e-6);
        assertEquals(2.223762, maxZ, 1e-6);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ModelCatalog.load("models/none.obj"));
        assertEquals("no such model in the game's resources: models/none.obj", e.getMessage());
    }

    @Test
    void theObjectToolPlacesAWindmillOnTheGroundAndItSurvivesMoveRotateUndoAndSave() throws Exception {
        CourseEditor e = EditorOperationsTest.flat(); // flat at h = 0.1
        ToolController tool = new ToolController(e);
        tool.setKind(ToolController.ObjectKind.MODEL);
        tool.modelFile = "models/windmill.obj";
        tool.modelScale = 0.5;
        tool.restitution = 0.4;
        assertEquals("placed model models/windmill.obj", tool.applyAt(0.5, 1.2));
        Obstacle.Model m = assertInstanceOf(Obstacle.Model.class, e.course().obstacles().get(0));
        assertEquals("models/windmill.obj", m.file());
        assertEquals(new Vec3(0.5, 1.2, 0.1), m.position());
        assertEquals(0.5, m.scale());
        assertEquals(0.4, m.restitution());
        assertEquals(0, m.rotationDeg());
        assertEquals(ModelCatalog.load("models/windmill.obj"), m.mesh());
        // Its tower (radius 0.45 m, scaled 0.225 m) is solid for the ball: a start inside it cannot reach the hole.
        e.setStart(0.5, 1.2);
        assertEquals(List.of("hole: no way from the start to the hole (A* on the course grid)"),
                e.validate().stream().map(Problem::message).toList());
        e.undo();
        assertEquals(List.of(), e.validate());

        e.moveObstacle(0, 1, -0.5);
        e.rotateObstacle(0, 30);
        Obstacle.Model moved = (Obstacle.Model) e.course().obstacles().get(0);
        assertEquals(new Vec3(1.5, 0.7, 0.1), moved.position());
        assertEquals(30, moved.rotationDeg(), 1e-12);
        e.undo();
        e.undo();
        assertEquals(m, e.course().obstacles().get(0));
        e.redo();
        e.redo();
        assertEquals(moved, e.course().obstacles().get(0));

        // Saved into a folder without models: the file string is kept and resolves from the game's resources.
        Path file = dir.resolve("windmill-mine.json");
        e.saveAs(file);
        assertTrue(Files.readString(file, StandardCharsets.UTF_8).contains("\"file\": \"models/windmill.obj\""));
        Course loaded = World.load(file).course();
        assertEquals(e.toCourse(), loaded);
        assertEquals(moved, loaded.obstacles().get(0));

        // Deleted with P under the tool, and back with undo.
        tool.moveTo(1.5, 0.7);
        assertEquals("deleted model models/windmill.obj", tool.deleteAt(1.5, 0.7));
        assertEquals(0, e.course().obstacles().size());
        e.undo();
        assertEquals(moved, e.course().obstacles().get(0));
    }

    @Test
    void anUnknownModelIsAMessageNotAnObject() {
        CourseEditor e = EditorOperationsTest.flat();
        ToolController tool = new ToolController(e);
        tool.setKind(ToolController.ObjectKind.MODEL);
        tool.modelFile = "models/none.obj";
        assertEquals("no such model in the game's resources: models/none.obj", tool.applyAt(0, 0));
        assertEquals(0, e.course().obstacles().size());
        assertFalse(e.canUndo());
    }

    @Test
    void wallTreeBoxAndModelSizesAndRestitutionAreUndoableEdits() throws Exception {
        CourseEditor e = EditorOperationsTest.flat();
        Obstacle.Wall wall = new Obstacle.Wall(new Vec2(-1, 1), new Vec2(1, 1), 0.05, 0.15, 0.7);
        Obstacle.Tree tree = new Obstacle.Tree(new Vec2(0, -1), 0.12, 1.2, 0.7);
        Obstacle.Box box = new Obstacle.Box(new Vec3(2, -1.4, 0.05), new Vec3(2.4, -1, 0.4), 30, 0.7);
        Obstacle.Model model = new Obstacle.Model("models/tree-crown.obj", new Vec3(-3, -1.5, 0.1), 0, 1,
                0.7, ModelCatalog.load("models/tree-crown.obj"));
        for (Obstacle o : List.of(wall, tree, box, model)) e.addObstacle(o);
        int before = e.historySize();

        e.setWallSize(0, 0.12, 0.3);
        assertEquals(new Obstacle.Wall(new Vec2(-1, 1), new Vec2(1, 1), 0.12, 0.3, 0.7), e.course().obstacles().get(0));
        assertEquals("wall size", e.undoLabel());
        e.setTreeSize(1, 0.2, 2);
        assertEquals(new Obstacle.Tree(new Vec2(0, -1), 0.2, 2, 0.7), e.course().obstacles().get(1));
        e.setBoxSize(2, 1.0, 0.6, 0.25); // keeps the centre (2.2, -1.2), the bottom 0.05 and the turn
        Obstacle.Box b = (Obstacle.Box) e.course().obstacles().get(2);
        assertEquals(1.7, b.min().x(), 1e-12);
        assertEquals(2.7, b.max().x(), 1e-12);
        assertEquals(-1.5, b.min().y(), 1e-12);
        assertEquals(-0.9, b.max().y(), 1e-12);
        assertEquals(0.05, b.min().z());
        assertEquals(0.3, b.max().z(), 1e-12);
        assertEquals(30, b.rotationDeg());
        e.setModelScale(3, 0.5);
        assertEquals(0.5, ((Obstacle.Model) e.course().obstacles().get(3)).scale());
        e.setRestitution(1, 0.35);
        assertEquals(0.35, e.course().obstacles().get(1).restitution());
        assertEquals(before + 5, e.historySize());
        // The same value again is no edit.
        e.setRestitution(1, 0.35);
        assertEquals(before + 5, e.historySize());

        // Save and load: every changed field comes back.
        Path file = dir.resolve("sizes.json");
        e.saveAs(file);
        assertEquals(e.toCourse(), World.load(file).course());

        // Undo all five: the objects are exactly as placed; redo all: as edited.
        List<Obstacle> edited = e.course().obstacles();
        for (int k = 0; k < 5; k++) assertTrue(e.undo());
        assertEquals(List.of(wall, tree, box, model), e.course().obstacles());
        for (int k = 0; k < 5; k++) assertTrue(e.redo());
        assertEquals(edited, e.course().obstacles());
        assertFalse(e.isDirty(), "redone back to the saved point");
    }

    @Test
    void badSizesAreRefusedWithAMessageAndChangeNothing() {
        CourseEditor e = EditorOperationsTest.flat();
        e.addObstacle(new Obstacle.Wall(new Vec2(-1, 1), new Vec2(1, 1), 0.05, 0.15, 0.7));
        e.addObstacle(new Obstacle.Tree(new Vec2(0, -1), 0.12, 1.2, 0.7));
        int size = e.historySize();
        assertEquals("wall thickness must be >= 0 and height > 0",
                assertThrows(IllegalArgumentException.class, () -> e.setWallSize(0, 0.05, 0)).getMessage());
        assertEquals("wall thickness must be >= 0 and height > 0",
                assertThrows(IllegalArgumentException.class, () -> e.setWallSize(0, -0.1, 0.2)).getMessage());
        assertEquals("object 1 is not a wall",
                assertThrows(IllegalArgumentException.class, () -> e.setWallSize(1, 0.1, 0.2)).getMessage());
        assertEquals("tree radius and height must be > 0",
                assertThrows(IllegalArgumentException.class, () -> e.setTreeSize(1, 0, 1)).getMessage());
        assertEquals("restitution must be between 0 and 2",
                assertThrows(IllegalArgumentException.class, () -> e.setRestitution(0, 2.5)).getMessage());
        assertEquals("no obstacle 5 (the course has 2)",
                assertThrows(IllegalArgumentException.class, () -> e.setRestitution(5, 0.5)).getMessage());
        assertEquals(size, e.historySize());
        // A thin fence (thickness 0) is allowed.
        e.setWallSize(0, 0, 0.2);
        assertEquals(0, ((Obstacle.Wall) e.course().obstacles().get(0)).thickness());
    }

    @Test
    void frictionZonesOfAnOpenedCourseAreListedEditedAndDeletedWithUndo() throws Exception {
        CourseEditor e = CourseEditor.open(Path.of("courses/sand.json"));
        List<Zone> zones = e.zones();
        assertEquals(3, zones.size());
        assertInstanceOf(Shape.Circle.class, zones.get(1).shape());
        assertEquals("circle (3.00, 1.50) r 1.00, mu_k 0.35 mu_s 0.45", ZoneTools.describe(zones.get(1)));
        assertEquals(0.35, e.world().friction().kinetic(3, 1.5), 0);

        e.removeZone(1);
        assertEquals(List.of(zones.get(0), zones.get(2)), e.zones());
        assertEquals(0.1, e.world().friction().kinetic(3, 1.5), 0, "the course's own friction where the circle was");
        assertEquals("delete zone", e.undoLabel());
        e.undo();
        assertEquals(zones, e.zones());
        assertEquals(0.35, e.world().friction().kinetic(3, 1.5), 0);
        e.redo();
        assertEquals(2, e.zones().size());

        e.setZoneFriction(0, 0.7, 0.8);
        assertEquals(new Zone(zones.get(0).shape(), 0.7, 0.8), e.zones().get(0));
        assertEquals(0.7, e.world().friction().kinetic(0, -1), 0);
        assertThrows(IllegalArgumentException.class, () -> e.setZoneFriction(0, -1, 0.8));
        assertThrows(IllegalArgumentException.class, () -> e.removeZone(2));

        Path file = dir.resolve("sand-edited.json");
        e.saveAs(file);
        Course loaded = World.load(file).course();
        assertEquals(List.of(new Zone(zones.get(0).shape(), 0.7, 0.8), zones.get(2)), loaded.zones());
        assertEquals(e.toCourse(), loaded);
        e.undo();
        e.undo();
        assertEquals(zones, e.zones());
    }
}
