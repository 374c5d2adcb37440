package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** "Save as" suggests the player's courses folder (which the game lists), never the installation's. */
class SaveLocationTest {
    @TempDir
    Path config;

    @Test
    void aNewCourseGoesToTheUsersCoursesFolderUnderItsName() throws Exception {
        assertEquals(config.resolve("courses").resolve("windy-hill-2.json"), SaveLocation.suggest(config, null, "Windy Hill #2"));
        assertEquals(config.resolve("courses").resolve("my-course.json"), SaveLocation.suggest(config, null, "  ?? "));
        Files.createDirectories(config.resolve("courses"));
        Files.writeString(config.resolve("courses").resolve("pond.json"), "{}");
        assertEquals(config.resolve("courses").resolve("pond-2.json"), SaveLocation.suggest(config, null, "Pond"), "not over another course");
        Path own = Path.of("/somewhere/else.json");
        assertEquals(own, SaveLocation.suggest(config, own, "Pond"), "a course with a file: that file");
        assertEquals(40, SaveLocation.stem("x".repeat(60)).length());
    }
}
