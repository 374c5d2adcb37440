package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The practice holes of issue 24 (courses/practice/) are offered as single holes after the rounds' holes. */
class PracticeHolesListedTest {
    @TempDir
    Path config;

    @Test
    void everyPracticeHoleIsListedOnceAfterTheRoundsHoles() {
        List<CourseFolders.CourseEntry> all = CourseFolders.list(new SettingsStore(config));
        List<String> practice = all.stream().filter(e -> e.file().getParent().getFileName().toString().equals("practice"))
                .map(e -> e.file().getFileName().toString()).sorted().toList();
        assertEquals(List.of("bumpers.json", "gatekeepers.json", "magnets.json", "one-way.json", "push-tiles.json",
                "teleport.json", "windmill.json"), practice);
        // After the rounds' holes, each once.
        int first = all.indexOf(all.stream().filter(e -> e.file().getParent().getFileName().toString().equals("practice"))
                .findFirst().orElseThrow());
        assertEquals(first, all.stream().filter(e -> !e.file().getParent().getFileName().toString().equals("practice")).count());
    }
}
