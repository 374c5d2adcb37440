package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ClassicIndexTest {
    /**
     * Found by ClassicTracksFuzzTest: a course path with a NUL character threw InvalidPathException
     * out of the reader (and out of the game's course list); such entries are left out, as those outside the folder.
     */
    @Test
    void entriesThatNameNoPathOrLeaveTheFolderAreLeftOut(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("index.json"), """
                {"format": 1, "tracks": [
                  {"name": "Nul", "author": "a", "course": "courses/x\\u0000y/course.json"},
                  {"name": "Out", "author": "a", "course": "../elsewhere/course.json"},
                  {"name": "Kept", "author": "a", "course": "courses/kept/course.json", "plays": 7}],
                 "failed": [{"source": "basic/b.track", "reason": "line 4 (T): the map data ends early"}]}
                """);
        ClassicIndex.Index index = ClassicIndex.read(dir);
        assertEquals(List.of("Kept"), index.tracks().stream().map(ClassicIndex.Entry::name).toList());
        assertEquals(dir.toAbsolutePath().normalize().resolve("courses/kept/course.json"), index.tracks().get(0).course());
        assertEquals("kept", index.tracks().get(0).folder());
        assertEquals(List.of("basic/b.track: line 4 (T): the map data ends early"), index.failed());
    }
}
