package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Teleports (docs/course-format.md, "Teleports"): in at the entry, out at an exit with the same speed. */
class TeleportTest {
    static final World TELEPORT = ElementWorlds.flat("\"teleports\": [{\"entry\": {\"type\": \"circle\", \"center\": [1, 0], \"radius\": 0.2},"
            + " \"exits\": [{\"position\": [-2, -3], \"directionDeg\": 90}, {\"position\": [-3, 2]}]}]");

    @Test
    void theBallKeepsItsSpeedAndTakesTheExitsDirection() {
        // Reaches the entry's edge (x = 0.8) at v1, leaves (-2, -3) upwards at v1, and rolls v1^2/(2 mu g).
        ShotResult r = ElementWorlds.simulator(TELEPORT).simulate(0, 0, 2, 0, 0, null);
        double mg = 0.981, v1 = Math.sqrt(4 - 2 * mg * 0.8);
        assertEquals(-2, r.endX(), 1e-12);
        assertEquals(-3 + v1 * v1 / (2 * mg), r.endY(), 1e-5);
        StrokeEvent e = r.events().get(0);
        assertEquals(StrokeEvent.Type.TELEPORT, e.type());
        assertEquals(-2, e.x());
        assertEquals(-3, e.y());
        assertEquals((2 - v1) / mg, e.t(), 1e-4);
    }

    @Test
    void exitsAreTakenInTurnAndAnExitWithoutDirectionKeepsTheBalls() {
        // The first exit sends the ball up the line x = -2 towards nothing; a course whose first exit
        // leads back into the entry shows the second exit is next: it keeps the ball's heading (+x).
        World loop = ElementWorlds.flat("\"teleports\": [{\"entry\": {\"type\": \"rect\", \"min\": [1, -0.3], \"max\": [1.2, 0.3]},"
                + " \"exits\": [{\"position\": [0.5, 0]}, {\"position\": [-3, 2]}]}]");
        ShotResult r = ElementWorlds.simulator(loop).simulate(0, 0, 3, 0, 0, null);
        List<StrokeEvent> teleports = r.events().stream().filter(e -> e.type() == StrokeEvent.Type.TELEPORT).toList();
        assertEquals(2, teleports.size());
        assertEquals(0.5, teleports.get(0).x());
        assertEquals(-3, teleports.get(1).x());
        assertEquals(2, r.endY(), 1e-12);
        double mg = 0.981;
        double v1 = Math.sqrt(9 - 2 * mg * 1), v2 = Math.sqrt(v1 * v1 - 2 * mg * 0.5);
        assertEquals(-3 + v2 * v2 / (2 * mg), r.endX(), 1e-5);
    }

    @Test
    void aFastBallCrossingACornerOfTheEntryInsideOneStepIsCaught() {
        // Near 5 m/s a step is about 80 mm; the shot's line y = x/4 cuts 62 mm across the entry's corner.
        World corner = ElementWorlds.flat("\"teleports\": [{\"entry\": {\"type\": \"rect\", \"min\": [1.9, 0.5], \"max\": [2.06, 1]},"
                + " \"exits\": [{\"position\": [-4, -4]}]}]");
        ShotResult r = ElementWorlds.simulator(corner).simulate(0, 0, 4.8, 1.2, 0, null);
        assertEquals(StrokeEvent.Type.TELEPORT, r.events().get(0).type());
    }

    @Test
    void anExitInsideAnEntryFromACourseBuiltInCodeTakesTheBallOutOfPlayInsteadOfLooping() {
        // The loader refuses such a course; one built in code (the editor's unsaved course) must not hang.
        World plain = ElementWorlds.flat("");
        minigolf.course.Teleport loop = new minigolf.course.Teleport(
                new minigolf.course.Shape.Circle(new minigolf.course.Vec2(1, 0), 0.3),
                List.of(new minigolf.course.Teleport.Exit(new minigolf.course.Vec2(1.1, 0), null)));
        World w = new World(plain.course().withElements(List.of(), List.of(), List.of(loop)), plain.terrain());
        ShotResult r = ElementWorlds.simulator(w).simulate(0, 0, 2, 0, 0, null);
        assertEquals(Outcome.OUT, r.outcome());
        assertEquals(0, r.endX());
        assertEquals(0, r.endY());
    }

    /**
     * A seeded teleport (the classic tracks' rule) draws its exit: the same shot draws the same exit,
     * and over many shots each of three exits comes about a third of the time. The entry here is a
     * grid of cells (as the classic importer writes), which a fast step must not jump.
     */
    @Test
    void aSeededTeleportDrawsItsExitTheSameForTheSameShot() {
        World plain = ElementWorlds.flat("");
        // Cells of 0.1 m from (0, -1): columns 10..11 (x 1.0 to 1.2), rows 9..10 (y -0.1 to 0.1).
        minigolf.course.Shape entry = new minigolf.course.Shape.Cells(new minigolf.course.Vec2(0, -1), 0.1, 40, 20,
                new int[] {9, 10, 12, 10, 10, 12});
        List<minigolf.course.Teleport.Exit> exits = List.of(
                new minigolf.course.Teleport.Exit(new minigolf.course.Vec2(-3, -2), null),
                new minigolf.course.Teleport.Exit(new minigolf.course.Vec2(-3, 0), null),
                new minigolf.course.Teleport.Exit(new minigolf.course.Vec2(-3, 2), null));
        minigolf.course.Teleport t = new minigolf.course.Teleport(entry, exits, 28L);
        World w = new World(plain.course().withElements(List.of(), List.of(), List.of(t)), plain.terrain());
        Simulator s = ElementWorlds.simulator(w);
        int[] count = new int[3];
        for (int k = 0; k < 300; k++) {
            double speed = 2 + k * 0.0035; // below 3.13 m/s: the ball does not roll back into the entry
            ShotResult r = s.simulate(0, 0, speed, 0, 0, null);
            StrokeEvent e = r.events().get(0);
            assertEquals(StrokeEvent.Type.TELEPORT, e.type());
            assertEquals(-3, e.x());
            count[(int) Math.round(e.y() / 2) + 1]++;
            // Out at the exit with the speed it had at the entry's edge (x = 1), on along +x.
            double mg = 0.981, v1Squared = speed * speed - 2 * mg * 1;
            assertEquals(-3 + v1Squared / (2 * mg), r.endX(), 1e-5);
            assertEquals(r, s.simulate(0, 0, speed, 0, 0, null));
        }
        for (int c : count) assertTrue(c > 60 && c < 140, java.util.Arrays.toString(count));
        // At 4.8 m/s a step is about 80 mm: the 0.2 m entry is still met, at its edge (x = 1).
        StrokeEvent fast = s.simulate(0, 0, 4.8, 0, 0, null).events().get(0);
        assertEquals(StrokeEvent.Type.TELEPORT, fast.type());
        assertEquals((4.8 - Math.sqrt(4.8 * 4.8 - 2 * 0.981)) / 0.981, fast.t(), 1e-4);
    }
}
