package minigolf.game;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A settings file the game cannot use is told in a player's words: which setting, what it may be in
 * the game's units, what the file has; never a raw double such as 4.9E-324 and never a path. The
 * terminal's line (the file's field and value) stays as it was (SettingsStoreTest).
 */
class SettingWordsTest {
    @TempDir
    Path dir;

    private String forPlayer(String json) throws Exception {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), json);
        return assertThrows(SettingsException.class, store::load).forPlayer();
    }

    @Test
    void aNumberOutOfRangeNamesTheSettingItsRangeAndTheValueInTheGamesUnits() throws Exception {
        String step = "; it must be 1 to 33 ms (1/1000 to 1/30 of a second).";
        assertEquals("The expert setting \"dt\" (the physics step) is almost 0 ms" + step, forPlayer("{\"dt\": 4.9e-324}"));
        assertEquals("The expert setting \"dt\" (the physics step) is 5000 ms" + step, forPlayer("{\"dt\": 5}"));
        assertEquals("The expert setting \"dt\" (the physics step) is 0.5 ms" + step, forPlayer("{\"dt\": 0.0005}"));
        assertEquals("The expert setting \"dt\" (the physics step) is empty (null)" + step, forPlayer("{\"dt\": null}"));
        String frames = "; it must be a whole number from 0 (no limit) to 1000 frames a second.";
        assertEquals("The frame limit is over a million" + frames, forPlayer("{\"frameLimit\": 99999999999}"));
        assertEquals("The frame limit is 2.5" + frames, forPlayer("{\"frameLimit\": 2.5}"));
        // Checked by the settings themselves (UserSettings), not by the file's reader.
        assertEquals("The mouse speed is 50 times the normal speed; it must be 0.1 to 10 times the normal speed.",
                forPlayer("{\"mouseSpeed\": 50}"));
        assertEquals("Realistic play's spread of a stroke's start is 75 cm; it must be 0 to 50 cm.",
                forPlayer("{\"noisePosition\": 0.75}"));
        assertEquals("The stroke limit is 0; it must be a whole number from 1 to 99 strokes a hole.",
                forPlayer("{\"strokeLimit\": 0}"));
    }

    @Test
    void choicesSwitchesSizesNamesAndFolders() throws Exception {
        assertEquals("The expert setting \"integrator\" (the physics method) is \"verlet\"; it must be euler, rk2 or rk4.", forPlayer("{\"integrator\": \"verlet\"}"));
        assertEquals("The graphics quality is \"ultra\"; it must be auto, high or low.", forPlayer("{\"graphics\": \"ultra\"}"));
        assertEquals("Vsync is \"yes\"; it must be true (on) or false (off).", forPlayer("{\"vsync\": \"yes\"}"));
        assertEquals("The aim guide is 1; it must be true (on) or false (off).", forPlayer("{\"aimGuide\": 1}"));
        String window = "; it must be 640 to 16384 by 480 to 16384 pixels, or 0 x 0 for the default 1280 x 720.";
        assertEquals("The window size is 300 x 200 pixels" + window, forPlayer("{\"windowWidth\": 300, \"windowHeight\": 200}"));
        assertEquals("The window size is 99999 x 0 pixels" + window, forPlayer("{\"windowWidth\": 99999}"));
        String names = "; it must be 1 to 4 names of 1 to 24 characters.";
        assertEquals("The player names list is a list with an empty name" + names, forPlayer("{\"playerNames\": [\"Ann\", \" \"]}"));
        assertEquals("The player names list is 5 names" + names, forPlayer("{\"playerNames\": [\"A\", \"B\", \"C\", \"D\", \"E\"]}"));
        assertEquals("The player names list holds 7" + names, forPlayer("{\"playerNames\": [\"Ann\", 7]}"));
        // A folder is a path: its length is said, not where it is.
        assertEquals("The classic tracks folder is a name of 5000 characters; it must be a folder name of at most 4096 characters.",
                forPlayer("{\"classicFolder\": \"" + "x".repeat(5000) + "\"}"));
    }

    @Test
    void aFileThatHoldsNoSettingsIsSaidAsAWhole() throws Exception {
        assertEquals("It has a setting this game does not know: \"colour\".", forPlayer("{\"colour\": 1}"));
        assertEquals("Its text is broken at line 2, column 1 (it is not valid JSON).", forPlayer("{\"dt\": 0.01,\n}"));
        assertEquals("It is empty.", forPlayer(""));
        assertEquals("It holds no settings (its text must be one JSON object, { ... }).", forPlayer("[1]"));
        SettingsStore store = new SettingsStore(dir.resolve("folder"));
        Files.createDirectories(store.file());
        assertEquals("It could not be read (is a directory, not a file).",
                assertThrows(SettingsException.class, store::load).forPlayer());
    }

    @Test
    void theSettingsFormSaysTheSameWords() {
        UserSettings.InvalidSetting e = assertThrows(UserSettings.InvalidSetting.class,
                () -> UserSettings.DEFAULTS.withFrameLimit(2000));
        assertEquals("frameLimit", e.field());
        assertEquals("frameLimit must be 0 to 1000, got 2000", e.getMessage(), "the command line's words stay");
        assertEquals("The frame limit is 2000; it must be a whole number from 0 (no limit) to 1000 frames a second.", e.forPlayer());
        assertEquals("The window size is 320 x 240 pixels; it must be 640 to 16384 by 480 to 16384 pixels, or 0 x 0 for the default"
                + " 1280 x 720.", assertThrows(UserSettings.InvalidSetting.class,
                () -> UserSettings.DEFAULTS.withWindowSize(320, 240)).forPlayer());
    }

    @Test
    void numbersForAPlayer() {
        assertEquals("8.33", SettingWords.amount(1000.0 / 120));
        assertEquals("33.3", SettingWords.amount(100.0 / 3));
        assertEquals("almost 0", SettingWords.amount(Double.MIN_VALUE));
        assertEquals("almost 0", SettingWords.amount(-1e-300));
        assertEquals("1234", SettingWords.amount(1234.4));
        assertEquals("over a million", SettingWords.amount(1e300));
        assertEquals("below minus a million", SettingWords.amount(-2e6));
        assertEquals("0.1", SettingWords.amount(0.1));
    }
}
