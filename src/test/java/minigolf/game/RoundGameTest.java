package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A round hole after hole: the card, par, totals, the winner, and a save in the middle that resumes exactly. */
class RoundGameTest {
    @TempDir
    Path dir;

    private static final double MU_G = 0.1 * 9.81;

    /** Flat course, start (-3, 0), hole at (hx, 0): a putt of exactly the hole's distance stops in the cup. */
    private static World flat(double hx) throws Exception {
        return World.parse("{\"format\": 1, \"name\": \"Flat " + hx + "\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-3, 0], \"hole\": {\"position\": [" + hx + ", 0], \"radius\": 0.1}}", "flat");
    }

    private static Round threeHoles() throws Exception {
        return new Round("Three", List.of(new Round.Hole("a.json", 2, flat(1)), new Round.Hole("b.json", 3, flat(2)),
                new Round.Hole("c.json", 2, flat(0))), "test");
    }

    /** A straight putt along +x that rolls exactly d metres (v^2 = 2 mu g d). */
    private static double speedFor(double d) {
        return Math.sqrt(2 * MU_G * d);
    }

    private static void holeIn(Game g, int seat, double d) {
        assertEquals(seat, g.currentPlayer());
        assertEquals(Outcome.HOLED, g.play(speedFor(d), 0).outcome());
    }

    @Test
    void playsHoleAfterHoleWithParTotalsAndTheWinner() throws Exception {
        RoundGame rg = new RoundGame(threeHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 10);
        // Hole 1 (par 2, cup 4 m away): Ann holes in one; Bob leaves it 2 m short, then holes: 2.
        holeIn(rg.game(), 0, 4);
        assertEquals(Outcome.STOPPED, rg.game().play(speedFor(2), 0).outcome());
        holeIn(rg.game(), 1, 2);
        assertTrue(rg.isHoleOver());
        assertArrayEquals(new int[]{1, 2}, rg.finishHole());
        assertFalse(rg.isHoleOver());
        assertThrows(IllegalStateException.class, rg::finishHole);
        assertTrue(rg.nextHole());
        assertEquals(1, rg.holeIndex());
        assertEquals("Flat 2.0", rg.game().world().course().name());
        // Hole 2 (par 3, cup 5 m away): both putt 3 m, then hole from 2 m: 2 each.
        RoundScorecard mid = rg.scorecard();
        assertEquals(1, mid.holesPlayed());
        assertEquals(-1, mid.toPar(0));
        assertEquals(0, mid.toPar(1));
        assertTrue(mid.winners().isEmpty(), "no winner before the end");
        for (int seat = 0; seat < 2; seat++) assertEquals(Outcome.STOPPED, rg.game().play(speedFor(3), 0).outcome());
        holeIn(rg.game(), 0, 2);
        holeIn(rg.game(), 1, 2);
        rg.finishHole();

        // Saved after hole 2, with Ann's first putt on hole 3 played: the file resumes exactly.
        assertTrue(rg.nextHole());
        assertEquals(Outcome.STOPPED, rg.game().play(speedFor(1), 0).outcome());
        Path file = dir.resolve("round.json");
        SavedRounds.save(rg, file);
        RoundGame back = SavedRounds.load(file);
        assertEquals(SavedRounds.toJson(rg), SavedRounds.toJson(back));
        assertEquals(2, back.holeIndex());
        assertArrayEquals(rg.finishedScores()[1], back.finishedScores()[1]);
        assertEquals(rg.game().player(0), back.game().player(0));

        for (RoundGame g : List.of(rg, back)) {
            // Hole 3 (par 2, 3 m): Bob (farther away) holes in one; Ann, 2 m short, holes: 2.
            holeIn(g.game(), 1, 3);
            holeIn(g.game(), 0, 2);
            g.finishHole();
            assertTrue(g.isOver());
            assertFalse(g.nextHole());
            RoundScorecard card = g.scorecard();
            assertEquals(7, card.totalPar());
            assertEquals(5, card.rows().get(0).total());
            assertEquals(5, card.rows().get(1).total());
            assertEquals(-2, card.toPar(0));
            assertEquals(List.of(0, 1), card.winners(), "equal totals share the win");
            assertTrue(card.toText().contains("tied: Ann, Bob"), card.toText());
            assertTrue(card.toText().contains("-2"), card.toText());
        }
    }

    @Test
    void aPickedUpPlayerScoresTheLimitPlusOneAndLoses() throws Exception {
        Round one = new Round("One", List.of(new Round.Hole("a.json", 3, flat(1))), "test");
        RoundGame rg = new RoundGame(one, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.human("Bob")), 2);
        holeIn(rg.game(), 0, 4);
        rg.game().play(speedFor(0.5), 0);
        rg.game().play(speedFor(0.5), 0);
        rg.finishHole();
        RoundScorecard card = rg.scorecard();
        assertArrayEquals(new int[]{1}, card.rows().get(0).holes());
        assertArrayEquals(new int[]{3}, card.rows().get(1).holes());
        assertEquals(List.of(0), card.winners());
        assertEquals("-2", RoundScorecard.formatToPar(card.toPar(0)));
        assertEquals("E", RoundScorecard.formatToPar(card.toPar(1)));
    }

    @Test
    void savedRoundErrorsAreOneLine() throws Exception {
        RoundGame rg = new RoundGame(threeHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
        String json = SavedRounds.toJson(rg);
        SaveGameException e = assertThrows(SaveGameException.class,
                () -> SavedRounds.parse(json.replace("\"par\" : 3", "\"par\" : 12"), "s.json"));
        assertEquals("s.json: round.holes[1].par: must be 1 to 9, got 12", e.getMessage());
        e = assertThrows(SaveGameException.class,
                () -> SavedRounds.parse(json.replace("\"scores\" : [ ]", "\"scores\" : [ [ 1, 2 ] ]"), "s.json"));
        assertEquals("s.json: scores[0]: must hold one score for each of the 1 players", e.getMessage());
        e = assertThrows(SaveGameException.class, () -> SavedRounds.parse(json.replace("minigolf-saved-round", "x"), "s.json"));
        assertEquals("s.json: kind: must be \"minigolf-saved-round\" (is this a saved round?)", e.getMessage());
        // A hole whose definition is missing: the path once, not "round.holes[0].definition.round.holes[0].definition".
        e = assertThrows(SaveGameException.class, () -> SavedRounds.parse(withoutFirstDefinition(json), "s.json"));
        assertEquals("s.json: round.holes[0].definition: is missing", e.getMessage());
        // The current hole is a saved game inside the file: named by its path under "hole", not as "s.json (hole)".
        e = assertThrows(SaveGameException.class, () -> SavedRounds.parse(json.replaceFirst("\"strokeLimit\" : 10", "\"strokeLimit\" : 0"), "s.json"));
        assertEquals("s.json: hole.strokeLimit: must be 1 to 99, got 0", e.getMessage());
        assertTrue(SavedRounds.isSavedRound(json));
        assertFalse(SavedRounds.isSavedRound("{\"kind\": \"minigolf-saved-game\"}"));
    }

    private static String withoutFirstDefinition(String json) throws Exception {
        var mapper = new com.fasterxml.jackson.databind.ObjectMapper();
        var root = mapper.readTree(json);
        ((com.fasterxml.jackson.databind.node.ObjectNode) root.get("round").get("holes").get(0)).remove("definition");
        return mapper.writeValueAsString(root);
    }

    @Test
    void aSavedBundledRoundWithModelsLoadsBack() throws Exception {
        Round r = RoundLoader.load(RoundFilesTest.rounds().resolve("meadowbrook-9.json"));
        RoundGame rg = new RoundGame(r, SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
        for (int hole = 0; hole < 2; hole++) { // aces on holes 1 and 2, then on the windmill hole
            double[] v = RoundFilesTest.HOLE_IN_ONE[hole];
            assertEquals(Outcome.HOLED, rg.game().play(v[0], v[1]).outcome());
            rg.finishHole();
            rg.nextHole();
        }
        assertEquals("Windmill", rg.game().world().course().name());
        Path file = dir.resolve("bundled.json");
        SavedRounds.save(rg, file);
        RoundGame back = SavedRounds.load(file);
        assertEquals(r.name(), back.round().name());
        assertEquals(rg.game().world().course(), back.game().world().course());
        double[] v = RoundFilesTest.HOLE_IN_ONE[2];
        assertEquals(Outcome.HOLED, back.game().play(v[0], v[1]).outcome(), "the windmill hole plays as before");
    }

    /** The "realistic" setting in a round: every hole strays, each with its own stream, and a save resumes it exactly. */
    @Test
    void aNoisyRoundPlaysEveryHoleWithNoiseAndResumesExactly() throws Exception {
        minigolf.bot.NoiseModel noise = new minigolf.bot.NoiseModel(0.01, 0.05);
        RoundGame rg = new RoundGame(threeHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10, noise, 77);
        assertEquals(noise, rg.game().noise());
        // A putt aimed at the cup 4 m away strays: it does not stop exactly where aimed.
        ShotRecord first = rg.game().play(speedFor(3), 0);
        assertNotEquals(-3 + 3, first.endX(), 1e-6);
        while (!rg.game().isOver()) rg.game().play(speedFor(Math.abs(1 - rg.game().player(0).x())), 0.01);
        rg.finishHole();
        long seed1 = rg.game().noiseSeed();
        assertTrue(rg.nextHole());
        assertEquals(noise, rg.game().noise(), "hole 2 is played with the round's noise too");
        assertNotEquals(seed1, rg.game().noiseSeed(), "each hole has its own stream");
        rg.game().play(speedFor(2), 0);

        // Saved on hole 2 after a putt: the restored round plays the next putts and hole 3 alike.
        Path file = dir.resolve("noisy.json");
        SavedRounds.save(rg, file);
        RoundGame back = SavedRounds.load(file);
        assertEquals(noise, back.noise());
        for (RoundGame g : List.of(rg, back)) {
            while (!g.game().isOver()) g.game().play(speedFor(Math.abs(2 - g.game().player(0).x())), 0.02);
            g.finishHole();
            assertTrue(g.nextHole());
            g.game().play(speedFor(2.5), 0.1);
        }
        assertEquals(rg.game().noiseSeed(), back.game().noiseSeed());
        ShotRecord a = rg.game().history().get(0), b = back.game().history().get(0);
        assertEquals(a.endX(), b.endX(), 0.0);
        assertEquals(a.endY(), b.endY(), 0.0);
        assertArrayEquals(rg.finishedScores()[1], back.finishedScores()[1]);
    }

    /** A saved round keeps every finished hole's strokes: any hole can be watched again after a load. */
    @Test
    void aSavedRoundKeepsEveryFinishedHolesStrokes() throws Exception {
        RoundGame rg = new RoundGame(threeHoles(), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
        assertEquals(Outcome.STOPPED, rg.game().play(speedFor(2.5), 0.02).outcome());
        rg.game().play(speedFor(Math.hypot(1 - rg.game().player(0).x(), rg.game().player(0).y())), 0);
        while (!rg.game().isOver()) rg.game().play(speedFor(0.3), 0);
        rg.finishHole();
        List<ShotRecord> played = rg.holeStrokes(0);
        assertTrue(rg.nextHole());
        Path file = dir.resolve("strokes.json");
        SavedRounds.save(rg, file);
        RoundGame back = SavedRounds.load(file);
        assertEquals(played, back.holeStrokes(0));
        // The replay of the loaded hole ends where play did, to the bit.
        HoleReplay replay = new HoleReplay(back.round().hole(0).world(), SimulationSettings.DEFAULT, back.holeStrokes(0));
        for (ShotRecord r : played) {
            var result = replay.nextStroke(null).run();
            assertEquals(r.endX(), result.endX(), 0.0);
            assertEquals(r.endY(), result.endY(), 0.0);
        }
        // A save from before strokes were kept still loads; its holes just have none to watch.
        var tree = (com.fasterxml.jackson.databind.node.ObjectNode) new com.fasterxml.jackson.databind.ObjectMapper()
                .readTree(SavedRounds.toJson(rg));
        tree.remove("strokes");
        String old = tree.toString();
        RoundGame fromOld = SavedRounds.parse(old, "old.json");
        assertTrue(fromOld.holeStrokes(0).isEmpty());
    }
}
