package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.HighScores;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The course select shows, for each hole, its par and the best score on it (course select listed
 * names only): the par of the round it belongs to, the best of a round's hole or a practice game.
 */
class CourseSelectParTest {
    @TempDir
    Path dir;

    @Test
    void practiceOffersEveryHoleOfTheRoundsAndNoTestTerrain() {
        // Practice offered the engine's test terrains ("Plane", "Grid 256", "Sine Cross") and none of
        // the rounds' holes, though the README says any hole can be played alone.
        List<CourseFolders.CourseEntry> all = CourseFolders.list(new SettingsStore(dir));
        List<String> names = all.stream().map(CourseFolders.CourseEntry::name).toList();
        assertTrue(names.containsAll(List.of("First Tee", "Dogleg", "Windmill")), names.toString());
        assertTrue(names.stream().noneMatch(n -> n.equals("Plane") || n.equals("Grid 256") || n.equals("Sine Cross")), names.toString());
        assertEquals(all.size(), all.stream().map(c -> c.file().toAbsolutePath().normalize()).distinct().count(), "each file once");
        int rounds = 0;
        for (CourseFolders.RoundEntry r : CourseFolders.rounds(new SettingsStore(dir))) rounds += r.round().size();
        assertTrue(all.size() >= 18 && all.size() <= rounds, all.size() + " holes of " + rounds + " in the rounds");
    }

    @Test
    void eachHoleShowsItsParAndTheBestScoreOnIt() {
        GameApp app = new GameApp(GameLauncher.loadBundled("/courses/flat.json"), new GameApp.Options(null, null, 0, null,
                List.of(), 1, new SettingsStore(dir), false, false));
        CourseSelectScreen select = app.screens().courseSelect();
        app.setScreen(select);
        Path projectDir = Path.of(System.getProperty("minigolf.projectDir", "."));
        CourseFolders.CourseEntry windmill = new CourseFolders.CourseEntry("Windmill",
                projectDir.resolve("courses/holes/03-windmill.json"), false);
        HighScores scores = new HighScores();
        assertEquals("par 3  -  not played yet", select.parAndBest(windmill, scores), "Meadowbrook's hole 3 is a par 3");
        scores.recordHole("Meadowbrook 18", 2, List.of(Player.human("Ann")), new int[]{3});
        assertEquals("par 3  -  best 3 (Ann)", select.parAndBest(windmill, scores), "a round's hole 3");
        scores.recordHole(HighScores.practiceKey(windmill.name()), 0, List.of(Player.human("Bob")), new int[]{2});
        assertEquals("par 3  -  best 2 (Bob)", select.parAndBest(windmill, scores), "a practice game, better");
        CourseFolders.CourseEntry own = new CourseFolders.CourseEntry("Mine", dir.resolve("mine.json"), true);
        assertTrue(select.parAndBest(own, scores).startsWith("no par"), "a course in no round has no par");
    }
}
