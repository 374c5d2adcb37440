package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A course the editor saves into the player's courses folder is listed as soon as "Select course" opens again. */
class CourseListRefreshTest {
    @TempDir
    Path config;

    @Test
    void aCourseSavedMeanwhileIsListedAfterARefresh() throws Exception {
        GameApp app = new GameApp(GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE), new GameApp.Options(null, null, 0, null,
                List.of(), 1, new SettingsStore(config), false, false));
        CourseSelectScreen select = app.screens().courseSelect();
        List<CourseFolders.CourseEntry> before = select.courses();
        assertTrue(before.stream().noneMatch(CourseFolders.CourseEntry::own));
        // What the editor's "Save as" does by default (SaveLocation): <config>/courses/<name>.json.
        Path saved = minigolf.editor.SaveLocation.suggest(config, null, "My Windy Hill");
        Files.createDirectories(saved.getParent());
        String json = Files.readString(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "holes", "01-first-tee.json"))
                .replace("\"First Tee\"", "\"My Windy Hill\"");
        Files.writeString(saved, json);
        assertEquals(before.size(), select.courses().size(), "the list is kept while the screen shows it");
        select.show(); // opened again from the main menu's "Rounds and practice holes"
        List<CourseFolders.CourseEntry> after = select.courses();
        assertEquals(before.size() + 1, after.size());
        CourseFolders.CourseEntry mine = after.stream().filter(CourseFolders.CourseEntry::own).findFirst().orElseThrow();
        assertEquals("My Windy Hill", mine.name());
        assertEquals(saved, mine.file());
    }
}
