package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.BotCatalog;
import minigolf.game.BotConditions;
import minigolf.game.BotControl;
import minigolf.game.Game;
import minigolf.game.HoleReplay;
import minigolf.game.PlayerState;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.ShotRecord;
import minigolf.online.ClientMessage;
import minigolf.online.client.RoomMirror;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Replays of an online round ("Watch hole N again", which plays {@code RoundGame.holeStrokes} of the
 * round the window holds): a client never simulates the server's strokes, it only takes their
 * records in, yet every finished hole replays on the client to the bit where the server ended each
 * stroke, at the course clock the server hit it at (a turning windmill: the clock moves the blades),
 * and again after the round is saved and loaded as a hot-seat round is. Two holes, Ann against a
 * server bot.
 */
class OnlineReplayTest {
    @TempDir
    Path dir;

    @Test
    void everyHoleOfAnOnlineRoundReplaysWhereTheServerEndedItsStrokes() throws Exception {
        Path courses = Files.createDirectories(dir.resolve("courses"));
        Path holes = Files.createDirectories(courses.resolve("holes")), rounds = Files.createDirectories(courses.resolve("rounds"));
        Files.copy(TestServers.COURSES.resolve("practice").resolve("windmill.json"), holes.resolve("windmill.json"));
        Files.copy(TestServers.COURSES.resolve("flat.json"), holes.resolve("flat.json"));
        Files.writeString(rounds.resolve("two.json"), "{\"format\": 1, \"name\": \"Two\", \"holes\": ["
                + "{\"course\": \"../holes/windmill.json\", \"par\": 3}, {\"course\": \"../holes/flat.json\", \"par\": 2}]}");
        CourseCatalog catalog = CourseCatalog.load(courses, new PrintWriter(new StringWriter()));
        try (GameServer server = GameServer.start(TestServers.options(dir.resolve("s.db").toString()), catalog,
                new PrintWriter(new StringWriter())); TestClient ann = TestClient.to(server)) {
            ann.send(new ClientMessage.Create("Ann", "two", 2, List.of("straight"), false, 10));
            ann.await(m -> m.path("type").asText().equals("room") && m.path("status").asText().equals("playing"), "the start");
            while (!(ann.mirror.round() != null && ann.mirror.round().isOver())) {
                ann.awaitState(() -> ann.mirror.isMyTurn() || ann.mirror.round().isOver(), "Ann's turn or the end");
                if (!ann.mirror.isMyTurn()) continue;
                double[] v = straightAtTheHole(ann.mirror);
                ann.putt(v[0], v[1]);
            }
            RoundGame round = ann.mirror.round();
            assertEquals(2, round.holesFinished());
            List<ObjectNode> strokes = ann.seen.stream().filter(m -> m.path("type").asText().equals("stroke")).toList();
            int windmillStrokesAfterTheStart = 0;
            for (int h = 0; h < 2; h++) {
                int hole = h;
                List<ObjectNode> served = strokes.stream().filter(m -> m.path("hole").asInt() == hole).toList();
                List<ShotRecord> kept = round.holeStrokes(h);
                assertEquals(served.size(), kept.size(), "hole " + (h + 1) + ": the strokes the server sent");
                assertTrue(kept.stream().map(ShotRecord::player).distinct().count() == 2, "both players' strokes: " + kept);
                for (int i = 0; i < kept.size(); i++) {
                    ObjectNode s = served.get(i);
                    assertEquals(s.path("clock").asDouble(0), kept.get(i).clock(), 0, "the server's clock");
                    assertEquals(s.get("end").get(0).asDouble(), kept.get(i).endX(), 0);
                    if (h == 0 && kept.get(i).clock() > 0) windmillStrokesAfterTheStart++;
                }
                HoleReplay replay = new HoleReplay(round.round().hole(h).world(), round.game().settings(), kept);
                assertTrue(replay.matchesPlay(), "hole " + (h + 1) + " replayed on the client ends where the server's strokes did");
            }
            assertTrue(windmillStrokesAfterTheStart > 0, "the windmill hole's strokes were hit while its clock ran");

            Path save = dir.resolve("online-round.json");
            SavedRounds.save(round, save);
            RoundGame back = SavedRounds.load(save);
            for (int h = 0; h < 2; h++) {
                assertEquals(round.holeStrokes(h), back.holeStrokes(h));
                assertTrue(new HoleReplay(back.round().hole(h).world(), back.game().settings(), back.holeStrokes(h)).matchesPlay(),
                        "hole " + (h + 1) + " after a save and a load");
            }
        }
    }

    /** The cheap bot's putt (the physics guess straight at the hole) for Ann's ball, within the speed limit. */
    private static double[] straightAtTheHole(RoomMirror mirror) {
        Game g = mirror.round().game();
        int seat = mirror.seat();
        PlayerState p = g.player(seat);
        BotConditions now = BotConditions.of(g, seat, false);
        double[] v = BotCatalog.planner("straight").plan(g.world(), g.settings(), p.x(), p.y(), p.total(), mirror.seq(),
                new BotConditions(now.noise(), now.hideFriction(), now.ownStrokes(), mirror.clockAt(RoomMirror.nowMs())),
                new BotControl());
        double max = g.world().physics().maxSpeed(), speed = Math.hypot(v[0], v[1]);
        double k = speed > max ? max / speed : 1;
        return new double[]{v[0] * k, v[1] * k};
    }
}
