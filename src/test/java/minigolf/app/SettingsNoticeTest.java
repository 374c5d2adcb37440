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

/**
 * A broken settings file: the game starts with the defaults, shows why in a player's words until
 * dismissed, says it on stderr in the file's own words, keeps the file (settings.broken.json once new settings are saved).
 */
class SettingsNoticeTest {
    @TempDir
    Path dir;

    @Test
    void aBrokenSettingsFileIsShownUntilDismissedAndKept() throws Exception {
        SettingsStore store = BrokenSettings.in(dir);
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
        // The player reads which setting, its range in the game's units, what the file has (no raw
        // double), what is used instead and what became of the file; no path. A physics field is named
        // as the file has it and called expert: Settings never shows it (it is the editor's and the CLI's).
        assertEquals("Your settings file was not used.\n"
                + "The expert setting \"dt\" (the physics step) is almost 0 ms; it must be 1 to 33 ms (1/1000 to 1/30 of a second).\n"
                + "Every setting is at its default for now.\nYour file is kept: it is renamed settings.broken.json when new"
                + " settings are saved.", app.notice());
        // The terminal's line names the file, the field and the value as written.
        assertEquals("minigolf: settings ignored, the defaults are used: " + store.file()
                + ": dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 4.9E-324\n",
                captured.toString(StandardCharsets.UTF_8).replace("\r\n", "\n"));
        assertEquals(UserSettings.DEFAULTS, app.settings());
        assertEquals(BrokenSettings.TEXT, Files.readString(store.file()), "the file is not touched");
        app.dismissNotice();
        assertNull(app.notice());
        assertTrue(Files.exists(store.file()));
        // What the notice promises: new settings saved, the old file kept under that name.
        app.applySettings(app.settings().withAimGuide(false));
        assertEquals(BrokenSettings.TEXT, Files.readString(dir.resolve("settings.broken.json")));
        assertEquals(false, store.load().aimGuide());
    }
}
