package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
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
import minigolf.game.SettingsException;
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
        store.removeStaleTemporaries();
        UserSettings settings;
        String problem = null;
        try {
            settings = store.load();
        } catch (SettingsException e) {
            settings = UserSettings.DEFAULTS;
            problem = e.forPlayer(); // the player's view names no file and no field; the terminal's line does
            System.err.println("minigolf: settings ignored, the defaults are used: " + e.getMessage());
        }
        loadedSettings = settings;
        settingsProblem = problem;
        AudioSettings volumes;
        try {
            volumes = AudioSettings.load(AudioSettings.file(store.directory()));
        } catch (SaveGameException e) {
            volumes = AudioSettings.DEFAULTS;
            say.accept("Your sound volumes could not be read (" + e.problem() + "); the defaults are used");
        }
        audio = volumes;
        HighScores scores;
        try {
            scores = HighScores.load(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            scores = null;
            say.accept("The high scores could not be read (" + e.problem() + "); they are not kept this time");
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

    /** Why the settings file was ignored at start, in a player's words (no file, no field names), or null. */
    String settingsProblem() {
        return settingsProblem;
    }

    void saveSettings(UserSettings s) {
        try {
            store.save(s);
        } catch (SaveGameException e) {
            say.accept("Your settings could not be saved: " + e.problem());
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
            say.accept("Your sound volumes could not be saved: " + e.problem());
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
            say.accept("The scores could not be saved: " + e.problem());
            return;
        }
        if (!news(news).isEmpty()) say.accept(news(news));
    }

    /** A finished single-course game's scores: personal bests on that course (its practice "round"); saved at once. */
    void recordPractice(Game game) {
        if (highScores == null) return;
        int[] scores = game.scorecard().lines().stream().mapToInt(minigolf.game.ScoreLine::score).toArray();
        List<HighScores.Achievement> news = highScores.recordHole(HighScores.practiceKey(game.world().course().name()), 0,
                game.players(), scores);
        try {
            highScores.save(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            say.accept("The scores could not be saved: " + e.problem());
            return;
        }
        if (!news(news).isEmpty()) say.accept(news(news));
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
            say.accept("The scores could not be saved: " + e.problem());
            return;
        }
        if (!news(news).isEmpty()) say.accept(news(news));
    }

    /**
     * What the high scores say, a player at a time: "Ann: personal best on hole 3 (2, was 3), high
     * score #1  ·  Bob: first round 57". A hole in one is left out: the stroke's own message said it.
     */
    static String news(List<HighScores.Achievement> news) {
        Map<String, List<String>> byPlayer = new LinkedHashMap<>();
        for (HighScores.Achievement a : news) {
            if (a.what().equals(HighScores.HOLE_IN_ONE)) continue;
            byPlayer.computeIfAbsent(a.name(), k -> new ArrayList<>()).add(a.what());
        }
        List<String> out = new ArrayList<>();
        byPlayer.forEach((name, what) -> out.add(name + ": " + String.join(", ", what)));
        return String.join("  ·  ", out);
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
            say.accept(round != null ? "Round saved: Load saved game in the main menu goes on with it"
                    : "Game saved: Load saved game in the main menu goes on with it");
        } catch (SaveGameException e) {
            say.accept("The game could not be saved: " + e.problem());
        } catch (IOException e) {
            say.accept("The game could not be saved: " + e.getMessage());
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
