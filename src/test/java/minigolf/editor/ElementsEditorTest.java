package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.Magnet;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The editor's part of issue 24: the object tool places every element, their parameters are set
 * (each change one undoable edit), moving and turning a moving obstacle carries its motion, and a
 * saved course loads back equal. The windmill it places really blocks the lane at some moments.
 */
class ElementsEditorTest {
    @TempDir
    Path dir;

    @Test
    void theNKeyCyclesThroughEveryKindAndBackToTheWall() {
        ToolController t = new ToolController(EditorOperationsTest.flat());
        t.setKind(ToolController.ObjectKind.WALL);
        StringBuilder seen = new StringBuilder();
        for (int i = 0; i < ToolController.ObjectKind.values().length; i++) seen.append(t.press(EditorKey.NEXT_KIND)).append('|');
        assertEquals("object tool: tree|object tool: box|object tool: model|object tool: bumper|object tool: gate|"
                + "object tool: windmill|object tool: turning bar|object tool: sliding gate|object tool: push zone|"
                + "object tool: magnet|object tool: teleport|object tool: wall|", seen.toString());
    }

    @Test
    void everyElementIsPlacedWhereTheToolIsWithTheToolsSettings() {
        CourseEditor e = EditorOperationsTest.flat(); // flat at h = 0.1
        ToolController t = new ToolController(e);
        t.setKind(ToolController.ObjectKind.BUMPER);
        t.bumperRadius = 0.12;
        t.bumperRestitution = 1.4;
        assertEquals("placed bumper", t.applyAt(-3, 1).replaceAll(" \\(.*", ""));
        assertEquals(new Obstacle.Bumper(new Vec2(-3, 1), 0.12, 0.1, 1.4), e.course().obstacles().get(0));

        t.setKind(ToolController.ObjectKind.GATE);
        t.gateLength = 0.6;
        t.restitution = 0.5;
        t.applyAt(-2, 1);
        Obstacle.Gate gate = assertInstanceOf(Obstacle.Gate.class, e.course().obstacles().get(1));
        assertEquals(new Vec2(-2, 0.7), gate.from());
        assertEquals(new Vec2(-2, 1.3), gate.to());
        assertNear(new Vec2(1, 0), gate.passNormal()); // placed passing towards +x

        t.setKind(ToolController.ObjectKind.WINDMILL);
        t.motionPeriod = 3;
        t.applyAt(0, 0);
        Obstacle.Moving mill = assertInstanceOf(Obstacle.Moving.class, e.course().obstacles().get(2));
        Obstacle.Model blades = assertInstanceOf(Obstacle.Model.class, mill.body());
        assertEquals(ToolController.WINDMILL_BLADES, blades.file());
        assertEquals(new Vec3(0, 0, 0.63), blades.position(), "the hub 0.53 m above the ground (0.1)");
        assertEquals(new Motion.Rotate(new Vec3(0, 0, 0.63), new Vec3(1, 0, 0), 3, 0), mill.motion());

        t.setKind(ToolController.ObjectKind.TURNING_BAR);
        t.applyAt(2, 1);
        Obstacle.Moving bar = (Obstacle.Moving) e.course().obstacles().get(3);
        assertEquals(new Motion.Rotate(new Vec3(2, 1, 0.1), new Vec3(0, 0, 1), 3, 0), bar.motion());
        assertEquals(new Obstacle.Box(new Vec3(1.5, 0.97, 0.05), new Vec3(2.5, 1.03, 0.22), 0, 0.5), bar.body());

        t.setKind(ToolController.ObjectKind.SLIDING_GATE);
        t.applyAt(3, -1);
        Motion.Slide slide = assertInstanceOf(Motion.Slide.class, ((Obstacle.Moving) e.course().obstacles().get(4)).motion());
        assertEquals(List.of(new Vec3(0, 0, 0), new Vec3(0, 0.65, 0)), slide.path());

        t.setKind(ToolController.ObjectKind.PUSH_ZONE);
        t.pushSize = 1;
        t.pushStrength = 2;
        t.pushDirectionDeg = 90;
        assertEquals("placed push zone", t.applyAt(-1, -1));
        PushZone z = e.pushZones().get(0);
        assertEquals(new Shape.Rect(new Vec2(-1.5, -1.5), new Vec2(-0.5, -0.5)), z.shape());
        assertEquals(0, z.push().x(), 1e-15);
        assertEquals(2, z.push().y(), 1e-15);

        t.setKind(ToolController.ObjectKind.MAGNET);
        t.magnetRadius = 0.4;
        t.magnetStrength = -3;
        assertEquals("placed magnet", t.applyAt(1, -1.5));
        assertEquals(List.of(new Magnet(new Vec2(1, -1.5), 0.4, -3)), e.magnets());

        t.setKind(ToolController.ObjectKind.TELEPORT);
        t.teleportRadius = 0.2;
        t.exitDx = 1.5;
        t.exitDy = 0.5;
        assertEquals("placed teleport (exit at 1.00, 1.00)", t.applyAt(-0.5, 0.5));
        assertEquals(new Teleport(new Shape.Circle(new Vec2(-0.5, 0.5), 0.2), List.of(new Teleport.Exit(new Vec2(1, 1), null))),
                e.teleports().get(0));

        // Ten placements, ten undo steps; all of them undone the course is empty again, redone it is back.
        Course placed = e.toCourse();
        for (int i = 0; i < 8; i++) assertTrue(e.undo());
        assertEquals(List.of(), e.toCourse().obstacles());
        assertEquals(List.of(), e.pushZones());
        assertEquals(List.of(), e.teleports());
        assertFalse(e.undo());
        for (int i = 0; i < 8; i++) assertTrue(e.redo());
        assertEquals(placed, e.toCourse());
    }

    @Test
    void parametersAreSetAsOneUndoStepEachAndBadValuesSayWhatIsWrong() {
        CourseEditor e = EditorOperationsTest.flat();
        ToolController t = new ToolController(e);
        t.setKind(ToolController.ObjectKind.TURNING_BAR);
        t.motionPeriod = 4;
        t.applyAt(0, 0);
        t.setKind(ToolController.ObjectKind.BUMPER);
        t.applyAt(2, 1);
        t.setKind(ToolController.ObjectKind.GATE);
        t.applyAt(-2, 1);
        int steps = e.historySize();

        e.setMotionTiming(0, 2.5, 0.75);
        Motion m = ((Obstacle.Moving) e.course().obstacles().get(0)).motion();
        assertEquals(new Motion.Rotate(new Vec3(0, 0, 0.1), new Vec3(0, 0, 1), 2.5, 0.75), m);
        e.setBumperSize(1, 0.2, 0.15);
        assertEquals(new Obstacle.Bumper(new Vec2(2, 1), 0.2, 0.15, Obstacle.DEFAULT_BUMPER_RESTITUTION), e.course().obstacles().get(1));
        e.setRestitution(1, 1.8);
        assertEquals(1.8, e.course().obstacles().get(1).restitution());
        e.flipGate(2);
        assertNear(new Vec2(-1, 0), ((Obstacle.Gate) e.course().obstacles().get(2)).passNormal());
        assertEquals(steps + 4, e.historySize());
        e.undo();
        assertNear(new Vec2(1, 0), ((Obstacle.Gate) e.course().obstacles().get(2)).passNormal());

        assertEquals("the period must be between 0.2 and 3600 s",
                assertThrows(IllegalArgumentException.class, () -> e.setMotionTiming(0, 0.1, 0)).getMessage());
        assertEquals("object 1 does not move",
                assertThrows(IllegalArgumentException.class, () -> e.setMotionTiming(1, 2, 0)).getMessage());
        assertEquals("object 0 is not a bumper",
                assertThrows(IllegalArgumentException.class, () -> e.setBumperSize(0, 0.1, 0.1)).getMessage());
        assertEquals("bumper radius and height must be > 0",
                assertThrows(IllegalArgumentException.class, () -> e.setBumperSize(1, 0, 0.1)).getMessage());
        assertEquals("object 1 is not a gate",
                assertThrows(IllegalArgumentException.class, () -> e.flipGate(1)).getMessage());

        e.addPushZone(new PushZone(new Shape.Circle(new Vec2(1, -1), 0.5), new Vec2(1, 0)));
        e.addMagnet(new Magnet(new Vec2(-1, -1), 0.5, 2));
        assertEquals("a push must be at most 50 m/s^2", assertThrows(IllegalArgumentException.class,
                () -> e.setPushZone(0, new PushZone(new Shape.Circle(new Vec2(1, -1), 0.5), new Vec2(60, 0)))).getMessage());
        assertEquals("a magnet's radius must be > 0 and its strength within +-50 m/s^2", assertThrows(IllegalArgumentException.class,
                () -> e.setMagnet(0, new Magnet(new Vec2(-1, -1), 0, 2))).getMessage());
        assertEquals("no teleport 0 (the course has 0)",
                assertThrows(IllegalArgumentException.class, () -> e.setTeleport(0, null)).getMessage());
        int before = e.historySize();
        e.setMagnet(0, new Magnet(new Vec2(-1, -1), 0.5, 2)); // unchanged: no edit
        assertEquals(before, e.historySize());
    }

    @Test
    void movingAndTurningAMovingObstacleCarriesItsMotion() {
        CourseEditor e = EditorOperationsTest.flat();
        ToolController t = new ToolController(e);
        t.setKind(ToolController.ObjectKind.SLIDING_GATE);
        t.applyAt(0, 0);
        t.setKind(ToolController.ObjectKind.TURNING_BAR);
        t.applyAt(2, 0);
        e.moveObstacle(1, 0.5, 1);
        Obstacle.Moving bar = (Obstacle.Moving) e.course().obstacles().get(1);
        assertEquals(new Vec3(2.5, 1, 0.1), ((Motion.Rotate) bar.motion()).pivot());
        // A slide turned by 90 degrees slides along -x instead of +y; its offsets are relative, the body turns about its centre.
        e.rotateObstacle(0, 90);
        Motion.Slide s = (Motion.Slide) ((Obstacle.Moving) e.course().obstacles().get(0)).motion();
        assertEquals(-0.65, s.path().get(1).x(), 1e-12);
        assertEquals(0, s.path().get(1).y(), 1e-12);
        // The tool deletes it like any object, and the elements that are areas or points when nothing else is there.
        e.addTeleport(new Teleport(new Shape.Circle(new Vec2(-2, -1), 0.2), List.of(new Teleport.Exit(new Vec2(2, -1), 45.0))));
        e.addPushZone(new PushZone(new Shape.Rect(new Vec2(-3, -1.5), new Vec2(-1, -0.5)), new Vec2(0, 1)));
        assertEquals("deleted teleport", t.deleteAt(-2, -1));
        assertEquals("deleted push zone", t.deleteAt(-2.8, -1));
        assertEquals("no object under the tool", t.deleteAt(-2.8, -1));
        assertEquals(List.of(), e.teleports());
    }

    @Test
    void validationMarksTeleportExitsOutsideOrInWaterAndPointsInsideAnEntry() {
        CourseEditor e = EditorOperationsTest.flat(); // start (-2, 0), hole (2, 0)
        e.addTeleport(new Teleport(new Shape.Circle(new Vec2(-2, 0), 0.3),
                List.of(new Teleport.Exit(new Vec2(9, 0), null), new Teleport.Exit(new Vec2(1, 1), null))));
        e.addTeleport(new Teleport(new Shape.Circle(new Vec2(1, 1), 0.2), List.of(new Teleport.Exit(new Vec2(0, -1), null))));
        assertEquals(List.of("teleport 0 exit 0: (9.00, 0.00) is outside the course",
                        "start: (-2.00, 0.00) is inside the entry of teleport 0",
                        "teleport 0 exit 1: (1.00, 1.00) is inside the entry of teleport 1"),
                e.validate().stream().map(Problem::message).toList());
    }

    @Test
    void aPlacedWindmillBlocksTheLaneAtSomeMomentsAndTheCourseSavesAndLoadsBack() throws Exception {
        CourseEditor e = EditorOperationsTest.flat();
        ToolController t = new ToolController(e);
        t.setKind(ToolController.ObjectKind.WINDMILL);
        t.motionPeriod = 4;
        t.applyAt(0, 0);
        t.setKind(ToolController.ObjectKind.PUSH_ZONE);
        t.pushStrength = 0.5;
        t.applyAt(-3, 1.5);
        t.setKind(ToolController.ObjectKind.MAGNET);
        t.applyAt(3, 1.5);
        t.setKind(ToolController.ObjectKind.TELEPORT);
        t.exitDx = 0;
        t.exitDy = -3;
        t.applyAt(-3, 1.5 + 0.0); // inside the push zone: allowed, the loader only refuses exits in entries
        assertEquals(List.of(), e.validate());

        Simulator sim = new Simulator(e.world(), SimulationSettings.DEFAULT);
        int blocked = 0, through = 0;
        for (int k = 0; k < 16; k++) {
            ShotResult r = sim.simulateAt(k * 0.25, -1.5, 0, 2.2, 0, 0);
            if (r.endX() < -0.05) blocked++;
            if (r.endX() > 0.3 || r.outcome() == Outcome.HOLED) through++;
        }
        assertTrue(blocked >= 2 && through >= 2, "blocked " + blocked + ", through " + through + " of 16 moments");

        Path file = dir.resolve("mill.json");
        e.saveAs(file);
        Course loaded = World.load(file).course();
        assertEquals(e.toCourse(), loaded);
        assertEquals(1, loaded.pushZones().size());
        assertEquals(1, loaded.magnets().size());
        assertNull(loaded.teleports().get(0).exits().get(0).directionDeg());
    }

    private static void assertNear(Vec2 expected, Vec2 actual) {
        assertEquals(expected.x(), actual.x(), 1e-12, actual.toString());
        assertEquals(expected.y(), actual.y(), 1e-12, actual.toString());
    }
}
