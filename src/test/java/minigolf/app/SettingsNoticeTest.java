package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A broken settings file: the game starts with the defaults, shows why until dismissed, says it on stderr, keeps the file. */
class SettingsNoticeTest {
    @TempDir
    Path dir;

    @Test
    void aBrokenSettingsFileIsShownUntilDismissedAndKept() throws Exception {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), "{\"dt\": 4.9e-324}");
        World world = World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json"));
        PrintStream stderr = System.err;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
        GameApp app;
        try {
            app = new GameApp(world, new GameApp.Options(null, null, 0, null, List.of(), 1, store, false, false));
        } finally {
            System.setErr(stderr);
        }
        String problem = "dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 4.9E-324";
        // The player's view names no file; the terminal's line does.
        assertEquals("Your settings could not be read (" + problem + "); the defaults are used", app.notice());
        assertEquals("minigolf: settings ignored, the defaults are used: " + store.file() + ": " + problem + "\n",
                captured.toString(StandardCharsets.UTF_8).replace("\r\n", "\n"));
        assertEquals(UserSettings.DEFAULTS, app.settings());
        assertEquals("{\"dt\": 4.9e-324}", Files.readString(store.file()), "the file is not touched");
        app.dismissNotice();
        assertNull(app.notice());
        assertTrue(Files.exists(store.file()));
    }
}
