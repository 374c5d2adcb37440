package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import minigolf.app.GameLauncher;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/** Rules of a hot-seat game on the flat course (h = 0.1, mu_k = 0.1, start (-3, 0), hole (3, 0.5) r 0.1, maxSpeed 4). */
class GameTest {
    static final World FLAT = GameLauncher.loadBundled("/courses/flat.json");
    static final double MU_G = 0.1 * 9.81;

    /** The speed that stops after d metres on flat ground: v = sqrt(2 mu g d). */
    static double[] shot(double fromX, double fromY, double toX, double toY, double fraction) {
        double dx = toX - fromX, dy = toY - fromY, d = Math.hypot(dx, dy);
        double v = Math.sqrt(2 * MU_G * d * fraction);
        return new double[]{dx / d * v, dy / d * v};
    }

    static Game twoPlayers() {
        return new Game(FLAT, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 10);
    }

    @Test
    void scriptedTwoPlayerGameEndsWithTheRightScores() {
        Game g = twoPlayers();
        assertEquals(0, g.currentPlayer(), "teeing off: seat order");
        // Each ball on its own spot beside the tee (TeeSpots), 0.16 m apart across the line to the hole.
        PlayerState annTee = g.player(0), bobTee = g.player(1);
        assertEquals(0.16, Math.hypot(annTee.x() - bobTee.x(), annTee.y() - bobTee.y()), 1e-12);

        double[] half = shot(annTee.x(), annTee.y(), 3, 0.5, 0.5); // stops half-way to the hole
        ShotRecord r1 = g.play(half[0], half[1]);
        assertEquals(Outcome.STOPPED, r1.outcome());
        assertEquals(0, r1.player());
        assertEquals((annTee.x() + 3) / 2, g.player(0).x(), 1e-3, "half-way along x from her spot to 3");
        assertEquals((annTee.y() + 0.5) / 2, g.player(0).y(), 1e-3);
        assertEquals(1, g.currentPlayer(), "Bob tees off (and is farther from the hole)");

        ShotRecord r2 = g.play(-4, 0); // 1 m to the edge at x = -4: out of bounds
        assertEquals(Outcome.OUT, r2.outcome());
        assertEquals(-4.0, r2.endX(), 1e-6, "located where it crossed the bound");
        assertEquals(new PlayerState(bobTee.x(), bobTee.y(), 1, 1, PlayerStatus.PLAYING), g.player(1),
                "back to his spot, one penalty");
        assertEquals(1, g.currentPlayer(), "Bob is still the farthest");

        double[] full = shot(bobTee.x(), bobTee.y(), 3, 0.5, 1);
        assertEquals(Outcome.HOLED, g.play(full[0], full[1]).outcome());
        assertEquals(PlayerStatus.HOLED, g.player(1).status());
        assertEquals(0, g.currentPlayer(), "holed players are skipped");

        PlayerState ann = g.player(0);
        double[] finish = shot(ann.x(), ann.y(), 3, 0.5, 1);
        assertEquals(Outcome.HOLED, g.play(finish[0], finish[1]).outcome());
        assertTrue(g.isOver());
        assertEquals(-1, g.currentPlayer());

        Scorecard card = g.scorecard();
        assertEquals(new ScoreLine("Ann", 2, 0, PlayerStatus.HOLED, 2, 1), card.lines().get(0));
        assertEquals(new ScoreLine("Bob", 2, 1, PlayerStatus.HOLED, 3, 2), card.lines().get(1));
        assertEquals(4, g.history().size());
        assertThrows(IllegalStateException.class, () -> g.play(1, 0), "no shots after the end");
    }

    @Test
    void waterCostsAPenaltyAndPutsTheBallBack() {
        World lake = GameLauncher.loadBundled("/courses/lake.json");
        Game g = new Game(lake, SimulationSettings.DEFAULT, List.of(Player.human("Solo")), 10);
        // Straight at the lake in the middle (water within 0.918 m of the origin), downhill from (-3, 0).
        ShotRecord r = g.play(2, 0);
        assertEquals(Outcome.WATER, r.outcome());
        assertEquals(-0.918, r.endX(), 0.002, "entered the water at its edge");
        assertEquals(new PlayerState(-3, 0, 1, 1, PlayerStatus.PLAYING), g.player(0));
        assertEquals(2, g.player(0).total());
    }

    @Test
    void atEqualDistanceThePlayerWithFewerStrokesGoes() {
        World lake = GameLauncher.loadBundled("/courses/lake.json");
        Game g = new Game(lake, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 10);
        assertEquals(Outcome.WATER, g.play(2, 0).outcome());
        assertEquals(1, g.currentPlayer(), "both at the start; Bob has 0 strokes, Ann 2");
        g.play(0.5, 0); // Bob rolls 0.5^2 / (2 mu g) ~ 0.16 m, downhill a bit further, nearer the hole
        assertEquals(0, g.currentPlayer(), "Ann is farther now");
    }

    @Test
    void strokeLimitPicksUpAndScoresLimitPlusOne() {
        Game g = new Game(FLAT, SimulationSettings.DEFAULT, List.of(Player.human("A"), Player.human("B")), 3);
        // Seat 0 dribbles 0.5 m each time; seat 1 holes in one.
        double[] dribble = shot(-3, 0, 3, 0.5, 0.5 / 6.0208);
        g.play(dribble[0], dribble[1]);
        assertEquals(1, g.currentPlayer());
        double[] ace = shot(-3, 0, 3, 0.5, 1);
        assertEquals(Outcome.HOLED, g.play(ace[0], ace[1]).outcome());
        g.play(0.3, 0);
        assertEquals(0, g.currentPlayer());
        g.play(0.3, 0);
        assertEquals(PlayerStatus.PICKED_UP, g.player(0).status());
        assertTrue(g.isOver());
        assertEquals(4, g.scorecard().lines().get(0).score(), "limit 3 + 1");
        assertEquals(2, g.scorecard().lines().get(0).rank());
        assertEquals(1, g.scorecard().lines().get(1).score());
        assertEquals(1, g.scorecard().lines().get(1).rank());
    }

    @Test
    void maximumSpeedHolds() {
        Game g = twoPlayers();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> g.startShot(3, 3));
        assertTrue(e.getMessage().contains("exceeds the course's maxSpeed"), e.getMessage());
        assertFalse(g.isShotInFlight(), "a refused shot is not counted");
        assertEquals(0, g.player(0).strokes());
    }

    @Test
    void oneStrokeAtATime() {
        Game g = twoPlayers();
        double x0 = g.player(0).x();
        g.startShot(1, 0);
        assertThrows(IllegalStateException.class, () -> g.startShot(1, 0));
        assertThrows(IllegalStateException.class, g::completeShot, "not finished yet");
        assertEquals(0, g.currentPlayer(), "the rolling ball's owner keeps the turn");
        ShotRecord r = g.finishShotNow();
        assertEquals(x0 + 1 / (2 * MU_G), g.player(0).x(), 1e-4, "v^2 / (2 mu g) from Ann's spot");
        assertEquals(Outcome.STOPPED, r.outcome());
    }

    @Test
    void rejectsBadSetups() {
        assertThrows(IllegalArgumentException.class, () -> new Game(FLAT, SimulationSettings.DEFAULT, List.of(), 10));
        List<Player> five = List.of(Player.human("1"), Player.human("2"), Player.human("3"), Player.human("4"), Player.human("5"));
        assertThrows(IllegalArgumentException.class, () -> new Game(FLAT, SimulationSettings.DEFAULT, five, 10));
        assertThrows(IllegalArgumentException.class, () -> new Game(FLAT, SimulationSettings.DEFAULT, List.of(Player.human("x")), 0));
        assertThrows(IllegalArgumentException.class, () -> Player.bot("Robo", " "));
    }
}
