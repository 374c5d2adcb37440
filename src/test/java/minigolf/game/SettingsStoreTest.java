package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import minigolf.physics.Integrator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SettingsStoreTest {
    @TempDir
    Path dir;

    @Test
    void missingFileMeansDefaults() throws Exception {
        assertEquals(UserSettings.DEFAULTS, new SettingsStore(dir.resolve("none")).load());
    }

    @Test
    void roundTrip() throws Exception {
        SettingsStore store = new SettingsStore(dir.resolve("minigolf"));
        UserSettings s = UserSettings.DEFAULTS.withIntegrator(Integrator.EULER).withDt(1.0 / 120).withVsync(false)
                .withFrameLimit(144).withMouseSpeed(1.7).withStrokeLimit(6).withHeightColours(true)
                .withPlayerNames(List.of("Ann", "Bob")).withAimGuide(false).withAntiAliasing(true)
                .withFullscreen(true).withGraphics("low").withWindowSize(1600, 900);
        store.save(s);
        assertEquals(s, store.load());
        assertFalse(store.load().aimGuide(), "the pro setting survives");
        assertTrue(store.load().antiAliasing());
        assertEquals(1.0 / 120, store.load().simulation().dt(), 0.0, "dt survives exactly");
    }

    @Test
    void graphicsAndWindowSizeAreCheckedWithOneLine() throws Exception {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), "{\"graphics\": \"ultra\"}");
        SaveGameException e = assertThrows(SaveGameException.class, store::load);
        assertEquals(store.file() + ": graphics must be auto, high or low, got ultra", e.getMessage());
        Files.writeString(store.file(), "{\"windowWidth\": 300, \"windowHeight\": 200}");
        e = assertThrows(SaveGameException.class, store::load);
        assertEquals(store.file() + ": the window size must be 0 x 0 (the default) or 640 to 16384 x 480 to 16384, got 300 x 200",
                e.getMessage());
        Files.writeString(store.file(), "{\"graphics\": \"high\", \"windowWidth\": 1920, \"windowHeight\": 1080}");
        UserSettings s = store.load();
        assertEquals("high", s.graphics());
        assertEquals(1920, s.windowWidth());
        assertEquals(1080, s.windowHeight());
    }

    @Test
    void anAimGuideThatIsNotABooleanIsRefused() throws Exception {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), "{\"aimGuide\": \"yes\"}");
        assertThrows(SaveGameException.class, store::load);
        Files.writeString(store.file(), "{\"aimGuide\": false}");
        assertFalse(store.load().aimGuide());
        Files.writeString(store.file(), "{}");
        assertTrue(store.load().aimGuide(), "missing: the default, on");
    }

    @Test
    void brokenFileGivesOneLineAndTheDefaults() throws Exception {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), "{\"dt\": 5}");
        SaveGameException e = assertThrows(SaveGameException.class, store::load);
        assertEquals(store.file() + ": dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 5.0", e.getMessage());
        String[] problem = new String[1];
        assertEquals(UserSettings.DEFAULTS, store.loadOrDefaults(problem));
        assertEquals(e.getMessage(), problem[0]);
        Files.writeString(store.file(), "{\"integrator\": \"verlet\"}");
        assertEquals(store.file() + ": integrator: must be euler, rk2 or rk4",
                assertThrows(SaveGameException.class, store::load).getMessage());
        // The problem named is the real one: a null is not "missing", a huge number is still a whole number.
        Files.writeString(store.file(), "{\"dt\": null}");
        assertEquals(store.file() + ": dt: must be a number, got null", assertThrows(SaveGameException.class, store::load).getMessage());
        Files.writeString(store.file(), "{\"frameLimit\": 99999999999}");
        assertEquals(store.file() + ": frameLimit: must be 0 to 1000, got 99999999999",
                assertThrows(SaveGameException.class, store::load).getMessage());
        Files.writeString(store.file(), "{\"frameLimit\": 2.5}");
        assertEquals(store.file() + ": frameLimit: must be a whole number, got 2.5",
                assertThrows(SaveGameException.class, store::load).getMessage());
        Files.writeString(store.file(), "{\"colour\": 1}");
        assertTrue(assertThrows(SaveGameException.class, store::load).getMessage().contains("colour: unknown field"));
    }

    @Test
    void configFolderFollowsXdg() {
        assertEquals(Path.of("/t/cfg"), SettingsStore.configDirectory("/t/cfg", Map.of("XDG_CONFIG_HOME", "/x"), "/home/u"));
        assertEquals(Path.of("/x/minigolf"), SettingsStore.configDirectory(null, Map.of("XDG_CONFIG_HOME", "/x"), "/home/u"));
        assertEquals(Path.of("/home/u/.config/minigolf"), SettingsStore.configDirectory(null, Map.of("XDG_CONFIG_HOME", "rel"), "/home/u"));
        assertEquals(Path.of("/home/u/.config/minigolf"), SettingsStore.configDirectory("", Map.of(), "/home/u"));
    }
}
