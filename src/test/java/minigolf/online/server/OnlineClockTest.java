package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.online.ClientMessage;
import minigolf.online.client.RoomMirror;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Stroke;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An online room's course clock (moving obstacles) runs in real time on the server, and every
 * stroke is hit at the server's reading of it when the shot arrives, plus the shot's wait: never
 * at a client's. The clients reckon the same clock from the events, so their windows show the
 * obstacles moving between strokes. Courses: the practice windmill and gatekeepers holes.
 */
class OnlineClockTest {
    @TempDir
    Path dir;

    private GameServer serve(String... practiceHoles) throws Exception {
        Path courses = Files.createDirectories(dir.resolve("courses"));
        for (String hole : practiceHoles) {
            Files.copy(TestServers.COURSES.resolve("practice").resolve(hole + ".json"), courses.resolve(hole + ".json"));
        }
        CourseCatalog catalog = CourseCatalog.load(courses, new PrintWriter(new StringWriter()));
        return GameServer.start(TestServers.options(dir.resolve("s.db").toString()), catalog, new PrintWriter(new StringWriter()));
    }

    @Test
    void aShotIsHitAtTheServersClockAndTheClientsRunTheSameClock() throws Exception {
        World windmill = World.load(TestServers.COURSES.resolve("practice").resolve("windmill.json"));
        try (GameServer server = serve("windmill"); TestClient ann = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "windmill", 1, List.of(), false, 10));
            ObjectNode started = ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("playing"),
                    "the start");
            long startMs = RoomMirror.nowMs();
            assertEquals(0, started.get("clock").asDouble(), 0.5, "the round's clock starts at 0: " + started.get("clock"));
            Thread.sleep(1200);
            // The client reckons the clock has run 1.2 s, as the server's has.
            double reckoned = ann.mirror.clockAt(RoomMirror.nowMs());
            assertEquals((RoomMirror.nowMs() - startMs) / 1000.0, reckoned, 0.5);

            long sentMs = RoomMirror.nowMs();
            ann.send(new ClientMessage.Shot(0, 3.5, 0, 0, 0.25));
            ObjectNode stroke = ann.await("stroke");
            long receivedMs = RoomMirror.nowMs();
            double clock = stroke.get("clock").asDouble(), after = stroke.get("clockAfter").asDouble();
            // The server's reading when the shot arrived, plus the wait (before: only the waits, 0.25).
            assertTrue(clock >= (sentMs - startMs) / 1000.0 + 0.25 - 0.5 && clock <= (receivedMs - startMs) / 1000.0 + 0.25 + 0.5,
                    "hit at clock " + clock + ", the shot sent " + (sentMs - startMs) + " ms after the start");
            assertTrue(clock > 1.0, "not at the waits alone: " + clock);
            assertEquals(0.25, stroke.get("wait").asDouble(), 0);
            // That stroke, replayed by anyone at the clock the server names, ends where the server says.
            var start = stroke.get("start");
            Stroke replay = new Stroke(windmill, SimulationSettings.DEFAULT, start.get(0).asDouble(), start.get(1).asDouble(), 3.5, 0,
                    0, clock, null, false);
            replay.run();
            assertEquals(stroke.get("end").get(0).asDouble(), replay.result().endX(), 1e-9);
            assertEquals(after, replay.clock(), 1e-9, "clockAfter is the stroke's end");

            // The client's clock: the wait and the roll, then it runs on from clockAfter.
            double roll = after - clock;
            long runsAt = receivedMs + Math.round((0.25 + roll) * 1000);
            assertEquals(after, ann.mirror.clockAt(runsAt - 50), 0.1, "stands while the ball rolls");
            assertEquals(after + 2, ann.mirror.clockAt(runsAt + 2000), 0.1);
            // A resync (the snapshot's clock) agrees with what the client reckoned.
            Thread.sleep(Math.max(0, runsAt - RoomMirror.nowMs()) + 300);
            double before = ann.mirror.clockAt(RoomMirror.nowMs());
            ann.send(new ClientMessage.Sync());
            ObjectNode snapshot = ann.await("room");
            double told = snapshot.get("clock").asDouble();
            assertTrue(told >= after + 0.2, "the room's clock ran on after the ball stopped: " + told + " after " + after);
            assertEquals(before, told, 0.5);
            assertEquals(told, ann.mirror.clockAt(RoomMirror.nowMs()), 0.2);
        }
    }

    @Test
    void aServerBotIsHitAtTheMomentItPlannedForAndHolesTheGatekeepers() throws Exception {
        // The planner holes the gatekeepers hole in one stroke after a planned wait (docs/course-format.md, practice holes).
        try (GameServer server = serve("gatekeepers"); TestClient ann = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "gatekeepers", 2, List.of("planner"), false, 10));
            ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("playing"), "the start");
            ObjectNode mine = ann.putt(0.5, 0);
            ObjectNode bots = ann.await(m -> m.path("type").asText().equals("stroke") && m.path("seat").asInt() == 1, "the bot's stroke");
            assertEquals("holed", bots.get("outcome").asText(), bots.toString());
            assertEquals(1, bots.get("strokes").asInt());
            assertTrue(bots.get("clock").asDouble() >= mine.get("clockAfter").asDouble(), "the clock never goes back: " + bots);
        }
    }
}
