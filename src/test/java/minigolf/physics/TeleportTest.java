package minigolf.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
