package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.course.CourseWriter;
import minigolf.game.RoundGame;
import minigolf.online.ClientMessage;
import minigolf.physics.BrickPhysicsTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bricks online: the server plays every stroke on its own course state (the client sends only the
 * velocity; no message carries the state) and the client's round, settled from the server's
 * events, has the bricks broken exactly where the server's are.
 */
class OnlineBricksTest {
    @TempDir
    Path dir;

    @Test
    void theServerBreaksTheBrickAndTheClientSeesItBroken() throws Exception {
        Path courses = Files.createDirectories(dir.resolve("courses"));
        Files.writeString(courses.resolve("lane.json"), CourseWriter.toJson(BrickPhysicsTest.lane(2)));
        CourseCatalog catalog = CourseCatalog.load(courses, new PrintWriter(new StringWriter()));
        try (GameServer server = GameServer.start(TestServers.options(dir.resolve("s.db").toString()), catalog,
                new PrintWriter(new StringWriter())); TestClient ann = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "lane", 1, List.of(), false, 10));
            ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("playing"), "the start");
            int[][] left = {{1}, {0}};
            for (int k = 0; k < 2; k++) {
                ann.awaitState(() -> ann.mirror.isMyTurn(), "Ann's turn");
                int strokes = k;
                ann.putt(3, 0);
                ann.awaitState(() -> ann.mirror.round().game().player(0).strokes() == strokes + 1, "stroke " + (k + 1) + " settled");
                RoundGame round = ann.mirror.round();
                assertArrayEquals(left[k], round.game().courseState().hitsLeft(), "the client's bricks after stroke " + (k + 1));
                assertTrue(round.game().player(0).x() < 2, "bounced back off the brick: " + round.game().player(0));
            }
            // The third putt, from where the server left the ball, rolls through where the brick stood.
            ann.awaitState(() -> ann.mirror.isMyTurn(), "Ann's turn");
            double from = ann.mirror.round().game().player(0).x();
            ann.putt(3, 0);
            ann.awaitState(() -> ann.mirror.round().game().player(0).strokes() == 3, "stroke 3 settled");
            assertEquals(from + 9 / (2 * 0.981), ann.mirror.round().game().player(0).x(), 0.001);
        }
    }
}
