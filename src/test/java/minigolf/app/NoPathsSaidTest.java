package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Issue 23: no file paths in a player's view. A save that cannot be loaded is said without where it lies. */
class NoPathsSaidTest {
    @TempDir
    Path dir;

    @Test
    void aSaveThatCannotBeLoadedIsSaidWithoutItsPath() throws Exception {
        World tee = FirstTeeSession.tee();
        List<String> said = new ArrayList<>();
        PlaySession play = FirstTeeSession.saying(tee, dir.resolve("config"), said);
        Path broken = Files.writeString(dir.resolve("broken.json"), "{\"version\": ");
        Path folder = Files.createDirectory(dir.resolve("a-folder.json"));
        for (Path file : List.of(dir.resolve("missing.json"), broken, folder)) {
            said.clear();
            assertFalse(play.load(file), file.getFileName().toString());
            assertTrue(said.size() == 1 && said.get(0).startsWith("That save could not be loaded: "), said.toString());
            assertFalse(said.get(0).contains(dir.toString()), "no path: " + said.get(0));
        }
    }
}
