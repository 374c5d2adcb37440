package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Passing over a seat (an online player who dropped) and picking one up without a stroke. */
class GamePassOverTest {
    private static Game game(int limit) throws Exception {
        World flat = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json"));
        return new Game(flat, SimulationSettings.DEFAULT, List.of(Player.human("A"), Player.human("B"), Player.human("C")), limit);
    }

    @Test
    void thePassedOverSeatWaitsWhileAnotherCanPlayAndPlaysWhenOnlyItIsLeft() throws Exception {
        Game g = game(10);
        g.play(1, 0); // A is nearer the hole now: B (seat 1) and C tie farthest, B is the lower seat
        assertEquals(1, g.currentPlayer());
        g.passOver(1, true);
        assertEquals(2, g.currentPlayer(), "B is passed over: C plays");
        g.passOver(2, true);
        assertEquals(0, g.currentPlayer(), "B and C passed over: A plays though nearer");
        g.passOver(0, true);
        assertEquals(1, g.currentPlayer(), "everyone passed over: golf order again");
        g.passOver(0, false);
        g.passOver(1, false);
        g.passOver(2, false);
        assertEquals(1, g.currentPlayer());
    }

    @Test
    void aPickedUpSeatScoresTheLimitPlusOne() throws Exception {
        Game g = game(4);
        g.pickUp(0);
        assertEquals(PlayerStatus.PICKED_UP, g.player(0).status());
        assertEquals(5, g.scorecard().lines().get(0).score());
        assertThrows(IllegalStateException.class, () -> g.pickUp(0));
        g.pickUp(1);
        g.pickUp(2);
        assertTrue(g.isOver());
    }
}
