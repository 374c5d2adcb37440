package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.Stream;
import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.HighScores;
import minigolf.game.Player;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SavedRounds;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;

/**
 * The player's files in the settings folder: settings, volumes, high scores and saved games. A
 * broken file is never fatal and never overwritten by accident: its problem is said, the defaults
 * are used (a broken high-score file is then left alone), and every save is atomic (the stores').
 */
final class PlayerFiles {
    private final SettingsStore store;
    private final Consumer<String> say;
    private final UserSettings loadedSettings;
    /** Why the settings file was ignored, shown until dismissed; null when it loaded. */
    private final String settingsProblem;
    private AudioSettings audio;
    /** Null when the file is broken: it is then left alone. */
    private final HighScores highScores;

    PlayerFiles(SettingsStore store, Consumer<String> say) {
        this.store = store;
        this.say = say;
        String[] problem = new String[1];
        store.removeStaleTemporaries();
        loadedSettings = store.loadOrDefaults(problem);
        settingsProblem = problem[0];
        if (problem[0] != null) System.err.println("minigolf: settings ignored, the defaults are used: " + problem[0]);
        AudioSettings volumes;
        try {
            volumes = AudioSettings.load(AudioSettings.file(store.directory()));
        } catch (SaveGameException e) {
            volumes = AudioSettings.DEFAULTS;
            say.accept("volumes ignored: " + e.getMessage());
        }
        audio = volumes;
        HighScores scores;
        try {
            scores = HighScores.load(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            scores = null;
            say.accept("high scores ignored: " + e.getMessage());
        }
        highScores = scores;
    }

    /** The settings as loaded at start (the defaults when the file was broken). */
    /** Where the player's files are (the courses and rounds of his own are beside them). */
    SettingsStore store() {
        return store;
    }

    UserSettings loadedSettings() {
        return loadedSettings;
    }

    /** Why the settings file was ignored at start, or null. */
    String settingsProblem() {
        return settingsProblem;
    }

    void saveSettings(UserSettings s) {
        try {
            store.save(s);
        } catch (SaveGameException e) {
            say.accept("settings not saved: " + e.getMessage());
        }
    }

    AudioSettings volumes() {
        return audio;
    }

    void saveVolumes(AudioSettings v) {
        audio = v;
        try {
            v.save(AudioSettings.file(store.directory()));
        } catch (SaveGameException e) {
            say.accept("volumes not saved: " + e.getMessage());
        }
    }

    HighScores highScores() {
        return highScores;
    }

    /** Personal bests for the hole just finished, and the table once the round is over; saved at once. */
    void recordScores(RoundGame round, int[] holeScores) {
        if (highScores == null) return;
        String name = round.round().name();
        List<HighScores.Achievement> news = new ArrayList<>(highScores.recordHole(name, round.holeIndex(), round.players(), holeScores));
        if (round.isOver()) news.addAll(highScores.recordRound(name, round.scorecard(), round.players(), LocalDate.now()));
        try {
            highScores.save(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            say.accept("scores not saved: " + e.getMessage());
            return;
        }
        if (!news.isEmpty()) say.accept(String.join("; ", news.stream().map(a -> a.name() + ": " + a.what()).toList()));
    }

    /**
     * A single game on a classic track is over: the human players' scores go into the high scores
     * under {@code key} (hole 0), so the course select shows each player's best beside the human
     * average and best of the original game.
     */
    void recordClassic(String key, Game game) {
        if (highScores == null || !game.isOver()) return;
        int[] all = game.scorecard().lines().stream().mapToInt(minigolf.game.ScoreLine::score).toArray();
        List<Player> humans = new ArrayList<>();
        List<Integer> scores = new ArrayList<>();
        for (int s = 0; s < game.players().size(); s++) {
            if (game.players().get(s).isBot()) continue;
            humans.add(game.players().get(s));
            scores.add(all[s]);
        }
        if (humans.isEmpty()) return;
        List<HighScores.Achievement> news = highScores.recordHole(key, 0, humans,
                scores.stream().mapToInt(Integer::intValue).toArray());
        try {
            highScores.save(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            say.accept("scores not saved: " + e.getMessage());
            return;
        }
        if (!news.isEmpty()) say.accept(String.join("; ", news.stream().map(a -> a.name() + ": " + a.what()).toList()));
    }

    /** The best score any of {@code names} has on classic track {@code key}, or null. */
    Integer classicBest(String key, List<String> names) {
        if (highScores == null) return null;
        Integer best = null;
        for (String n : names) {
            Integer b = highScores.personalBest(key, 0, n);
            if (b != null && (best == null || b < best)) best = b;
        }
        return best;
    }

    /** Saves the round (when one is played) or the game into the saves folder under a dated name. */
    void save(Game game, RoundGame round) {
        try {
            Files.createDirectories(store.savesDirectory());
            Path file = store.savesDirectory().resolve((round != null ? "round-" : "game-")
                    + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")) + ".json");
            if (round != null) SavedRounds.save(round, file);
            else SavedGames.save(game, file);
            say.accept("saved to " + file);
        } catch (IOException | SaveGameException e) {
            say.accept("not saved: " + e.getMessage());
        }
    }

    /** The saved games and rounds, by name (oldest first: the names start with the date). */
    List<Path> savedGames() {
        Path dir = store.savesDirectory();
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
    }
}
