package minigolf.bot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The opponents' levels as calibrated (docs/bots.md, "Opponents with levels"), on a small part of
 * the tuning set: tile seed 1001's first six courses, two games each, and the Meadowbrook round
 * against a player who plays par. The figures on the fresh seeds are in docs/bots.md.
 */
class LevelCalibrationTest {
    /** planner-aces' strokes on tile courses 1001-0 to 1001-5 (LevelCalibration 1001 6 2). */
    private static final int[] FEWEST = {1, 2, 2, 2, 4, 2};

    private static LevelCalibration.LevelResult play(String level) {
        return LevelCalibration.play(level, TileCourses.generate(1001, FEWEST.length), FEWEST, 2, 1);
    }

    private static void assertBand(LevelCalibration.LevelResult r, double low, double high) {
        assertEquals(FEWEST.length, r.holed(), r.level() + " holes every game");
        assertTrue(r.maxStrokes() <= LevelCalibration.MAX_STROKES, r.level() + " within the stroke limit");
        assertTrue(r.median() >= low && r.median() <= high, r.level() + ": median ratio " + r.median() + " of "
                + Arrays.toString(r.ratios()));
    }

    @Test
    void eachLevelPlaysWithinItsBandOnTheTuningTiles() {
        // Measured (median of the six courses' mean strokes over the fewest; mean strokes a game), 28 Nov:
        // easy 3.25 (6.00; 3.00 and 5.42 at 5 degrees / 17% before), hard 1.38 (2.92), pro 1.13 (2.67);
        // medium 2.00 (4.17) on 27 Nov. The bands leave
        // room for small changes of the engine. Hard misses the ace of 1001-0 (2 strokes where pro
        // takes 1): it goes for a hole in one with medium's error and plays the rest nearly exactly.
        LevelCalibration.LevelResult easy = play("easy"), medium = play("medium"), hard = play("hard"), pro = play("pro");
        assertBand(easy, 2.4, 3.4);
        assertBand(medium, 1.7, 2.35);
        assertBand(hard, 1.1, 1.6);
        assertBand(pro, 1.0, 1.3);
        assertTrue(mean(easy) > mean(medium) && mean(medium) >= mean(hard) && mean(hard) > mean(pro),
                mean(easy) + " " + mean(medium) + " " + mean(hard) + " " + mean(pro));
    }

    @Test
    void easyHolesWithinTheLimitInTheGamesThatOnceRanPastIt() {
        // 28 Nov (easy 6 degrees / 20%, the error halving per stroke from the sixth): 12273404-15 (fewest 4)
        // took 9, 9 and 10 strokes, the third game not holed at 10; 44706668-6's second game took 11
        // (three times into the water from one spot: the planner's lay-up there is exact or wet).
        LevelCalibration.LevelResult maze = LevelCalibration.play("easy", List.of(TileCourses.generate(12273404, 16).get(15)),
                new int[]{4}, 3, 1);
        LevelCalibration.LevelResult water = LevelCalibration.play("easy", List.of(TileCourses.generate(44706668, 7).get(6)),
                new int[]{3}, 2, 1);
        for (LevelCalibration.LevelResult r : List.of(maze, water)) {
            assertEquals(1, r.holed(), "every game holed: " + Arrays.toString(r.courses().get(0).strokes()));
            assertTrue(r.maxStrokes() <= LevelCalibration.MAX_STROKES, Arrays.toString(r.courses().get(0).strokes()));
        }
    }

    private static double mean(LevelCalibration.LevelResult r) {
        return r.courses().stream().mapToDouble(LevelCalibration.CourseResult::mean).average().orElseThrow();
    }

    @Test
    void aParPlayerBeatsMediumAndLosesToHardOnMeadowbrook() throws Exception {
        Round round = RoundLoader.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/rounds/meadowbrook-18.json"));
        List<World> holes = round.holes().stream().map(Round.Hole::world).toList();
        int par = round.holes().stream().mapToInt(Round.Hole::par).sum();
        assertEquals(46, par);
        int[] medium = LevelCalibration.roundTotals("medium", holes, 3, 1), hard = LevelCalibration.roundTotals("hard", holes, 3, 1);
        // Measured (game seeds 1-3, a seed of its own for each hole): medium 48, 49, 49; hard 34, 36, 34
        // (a few seconds). Hard at a quarter of a degree and 1% of pace on every stroke scored 28, 29, 27
        // (the planner 21, with 15 aces; hard's attempts at aces now miss but about one a round).
        assertTrue(Arrays.stream(medium).filter(t -> t > par).count() >= 2, "medium above par: " + Arrays.toString(medium));
        assertTrue(Arrays.stream(hard).filter(t -> t < par).count() >= 2, "hard below par: " + Arrays.toString(hard));
        assertTrue(Arrays.stream(hard).allMatch(t -> t >= par - 14), "hard under par, not the planner's 21: "
                + Arrays.toString(hard));
        assertTrue(Arrays.stream(hard).max().getAsInt() < Arrays.stream(medium).min().getAsInt(),
                "hard beats medium every time: " + Arrays.toString(hard) + " " + Arrays.toString(medium));
    }
}
