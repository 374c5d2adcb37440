package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.course.CourseWriter;
import minigolf.physics.BrickPhysicsTest;
import minigolf.physics.CourseState;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Bricks in a game: what a stroke breaks stays broken for the strokes after it, in saves and replays; a new hole starts whole. */
class BrickGameTest {
    private static Game game(int hits) {
        return new Game(World.of(BrickPhysicsTest.lane(hits)), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
    }

    /** Four putts at 3 m/s into the brick (4 hits), each bouncing back; returns the game after them. */
    private static Game fourPutts() {
        Game g = game(4);
        for (int i = 1; i <= 4; i++) {
            ShotRecord r = g.play(3, 0);
            assertEquals(Outcome.STOPPED, r.outcome());
            assertTrue(r.endX() < 2, "putt " + i + " bounced back: x " + r.endX());
            assertArrayEquals(new int[]{4 - i}, g.courseState().hitsLeft(), "after putt " + i);
        }
        return g;
    }

    @Test
    void theBrickStaysBrokenForTheNextStroke() {
        Game g = fourPutts();
        double from = g.player(0).x();
        // The fifth putt rolls through where the brick stood, its full 3^2 / (2 * 0.981) = 4.59 m (or into the hole's row).
        ShotRecord fifth = g.play(3, 0);
        assertEquals(from + 9 / (2 * 0.981), fifth.endX(), 0.001);
        assertEquals(5, g.history().size());
        // The hole as it started is kept for replays.
        assertEquals(CourseState.initial(g.world().course()), g.startWorld().state());
    }

    @Test
    void aSaveMidHoleLoadsWithTheBricksAsPlayLeftThem() throws Exception {
        Game g = game(4);
        g.play(3, 0);
        g.play(3, 0);
        String json = SavedGames.toJson(g);
        assertTrue(!json.contains("courseState"), "the save holds the strokes, not the state");
        Game back = SavedGames.parse(json, "save.json").resume();
        assertArrayEquals(new int[]{2}, back.courseState().hitsLeft());
        // And it plays on as the unbroken game does, to the bit.
        ShotRecord a = g.play(3, 0), b = back.play(3, 0);
        assertEquals(a, b);
        assertArrayEquals(new int[]{1}, back.courseState().hitsLeft());
        // The course written into the save holds the bricks as the hole started.
        assertTrue(CourseWriter.toJson(back.world().course()).contains("\"hits\": 4"));
    }

    @Test
    void aReplayRebuildsTheBricksStrokeByStroke() {
        Game g = fourPutts();
        g.play(3, 0);
        HoleReplay replay = HoleReplay.of(g);
        assertTrue(replay.matchesPlay());
        // Played on the hole as it started, the fifth stroke would bounce off the brick: the replay must carry the state.
        ShotRecord fifth = g.history().get(4);
        var onWholeBrick = new minigolf.physics.Simulator(g.startWorld(), SimulationSettings.DEFAULT)
                .simulate(fifth.startX(), fifth.startY(), fifth.vx(), fifth.vy());
        assertNotEquals(fifth.endX(), onWholeBrick.endX());
        // Stepped stroke by stroke (as the replay screen does), the course before the fifth has the brick gone.
        for (int i = 0; i < 5; i++) {
            var s = replay.nextStroke(null);
            s.run();
            assertTrue(HoleReplay.sameEnd(g.history().get(i), s), "stroke " + i);
        }
        assertArrayEquals(new int[]{0}, replay.courseNow().state().hitsLeft());
    }

    @Test
    void aNewGameOnTheHoleStartsWithEveryBrickStanding() {
        Game g = fourPutts();
        Game next = new Game(g.world(), SimulationSettings.DEFAULT, List.of(Player.human("Bob")), 10);
        assertArrayEquals(new int[]{4}, next.courseState().hitsLeft());
    }
}
