package minigolf.online;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.game.Player;
import minigolf.game.PlayerStatus;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.ShotRecord;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * Settling a round from events (as clients and a restarting server do) gives exactly the round
 * the engine played: the same balls, counts, history, card and save.
 */
class RoundSyncTest {
    private static Round twoHoles() throws Exception {
        World flat = World.load(java.nio.file.Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json"));
        return new Round("Two flats", List.of(new Round.Hole("flat.json", 2, flat), new Round.Hole("flat.json", 3, flat)), "test");
    }

    @Test
    void eventsSettleToTheRoundThatWasPlayed() throws Exception {
        Round round = twoHoles();
        List<Player> players = List.of(Player.human("Ann"), Player.human("Bob"));
        RoundGame played = new RoundGame(round, SimulationSettings.DEFAULT, players, 2);
        RoundGame settled = SavedRounds.parse(SavedRounds.toJson(played), "start");
        long seq = 0;
        double[][] shots = {{1, 0}, {0.8, 0.1}, {0.5, 0}, {3.9, 0.2}, {1.2, -0.1}, {0.3, 0}, {2, 0}, {1, 1}};
        int k = 0;
        while (!played.isOver()) {
            int hole = played.holeIndex();
            int seat = played.game().currentPlayer();
            ShotRecord r = played.game().play(shots[k][0], shots[k][1]);
            k = (k + 1) % shots.length;
            RoomEvent e = new RoomEvent(++seq, hole, seat, r, played.game().player(seat), 0, played.game().clock());
            RoomEvent wire = RoomEvent.parse(Json.parse(Json.write(e.toJson(-1))), 2);
            assertEquals(e, wire, "an event reads back exactly (every double too)");
            minigolf.online.RoundSync.advance(played);
            settled = RoundSync.apply(settled, wire);
            assertEquals(played.holeIndex(), settled.holeIndex());
        }
        assertTrue(settled.isOver());
        assertEquals(played.scorecard().toText(), settled.scorecard().toText());
        assertEquals(SavedRounds.toJson(played), SavedRounds.toJson(settled), "the same save, strokes of every hole included");
    }

    @Test
    void bricksBrokenOnTheServerAreBrokenOnTheClientWithoutTheEventSayingSo() throws Exception {
        World lane = World.of(minigolf.physics.BrickPhysicsTest.lane(2));
        Round round = new Round("Bricks", List.of(new Round.Hole("lane.json", 3, lane), new Round.Hole("lane.json", 3, lane)), "test");
        List<Player> players = List.of(Player.human("Ann"), Player.human("Bob"));
        RoundGame server = new RoundGame(round, SimulationSettings.DEFAULT, players, 6);
        RoundGame client = SavedRounds.parse(SavedRounds.toJson(server), "start");
        long seq = 0;
        // Ann and Bob each putt into the 2-hit brick: after the second stroke it is gone for both.
        int[][] expected = {{1}, {0}, {0}};
        for (int k = 0; k < 3; k++) {
            int seat = server.game().currentPlayer();
            ShotRecord r = server.game().play(3, 0);
            RoomEvent e = new RoomEvent(++seq, 0, seat, r, server.game().player(seat), 0, server.game().clock());
            client = RoundSync.apply(client, RoomEvent.parse(Json.parse(Json.write(e.toJson(-1))), 2));
            assertEquals(List.of(expected[k][0]), List.of(server.game().courseState().hitsLeft(0)), "server, stroke " + k);
            assertEquals(server.game().courseState(), client.game().courseState(), "client, stroke " + k);
            assertEquals(server.game().player(seat), client.game().player(seat));
        }
    }

    @Test
    void aPickUpScoresTheLimitPlusOneAndAnEventOnTheWrongHoleIsRefused() throws Exception {
        Round round = twoHoles();
        RoundGame rg = new RoundGame(round, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 5);
        rg.game().pickUp(0);
        RoomEvent pick = new RoomEvent(1, 0, 0, null, rg.game().player(0), 0);
        RoundGame fresh = new RoundGame(round, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 5);
        RoundGame after = RoundSync.apply(fresh, pick);
        assertEquals(1, after.holesFinished());
        assertEquals(6, after.finishedScores()[0][0]);
        assertEquals(PlayerStatus.PICKED_UP, pick.after().status());
        RoomEvent wrongHole = new RoomEvent(2, 0, 0, null, pick.after(), 0);
        assertThrows(IllegalStateException.class, () -> RoundSync.apply(after, wrongHole));
    }

    @Test
    void theCourseClockOfAStrokeTravelsWithTheEventAndSettlesTheClientsClock() throws Exception {
        RoundGame rg = new RoundGame(twoHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 5);
        rg.game().advanceClock(3.5);
        ShotRecord r = rg.game().play(0.5, 0);
        assertEquals(3.5, r.clock());
        double after = rg.game().clock();
        assertTrue(after > 3.5, "the stroke's own time runs the clock on: " + after);
        RoomEvent e = new RoomEvent(1, 0, 0, r, rg.game().player(0), 3.5, after);
        String json = Json.write(e.toJson(0));
        assertTrue(json.contains("\"clock\":3.5,\"clockAfter\":" + after), json);
        RoomEvent wire = RoomEvent.parse(Json.parse(json), 1);
        assertEquals(e, wire);
        RoundGame fresh = new RoundGame(twoHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 5);
        assertEquals(after, RoundSync.apply(fresh, wire).game().clock());
        // A stroke at clock 0 leaves the field out, as before.
        RoundGame zero = new RoundGame(twoHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 5);
        ShotRecord first = zero.game().play(0.5, 0);
        assertTrue(!Json.write(new RoomEvent(1, 0, 0, first, zero.game().player(0), 0).toJson(0)).contains("clock"));
    }
}
