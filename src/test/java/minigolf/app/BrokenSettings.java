package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import minigolf.game.SettingsStore;

/**
 * The settings folder of a player whose settings file the game cannot use: a physics step of
 * 4.9e-324 s (the smallest double, far below the 1 ms allowed). What the game then shows is each
 * test's own assertion (SettingsNoticeTest: the words; NoticeAndBotPanelWindowTest: where).
 */
final class BrokenSettings {
    /** The file's text, as a hand edit might leave it. */
    static final String TEXT = "{\"dt\": 4.9e-324}";

    private BrokenSettings() {
    }

    /** A store in {@code dir} whose settings file holds {@link #TEXT}. */
    static SettingsStore in(Path dir) throws IOException {
        SettingsStore store = new SettingsStore(dir);
        Files.writeString(store.file(), TEXT);
        return store;
    }
}
