package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import minigolf.course.Limits;

/**
 * How a saved game is listed in the menu: by its round's name (or its course's, for a single
 * course), the hole's course, the players and when it was saved, not by its file name. Read from
 * the file's JSON without building the game; a file that cannot be read is listed by its name.
 */
public record SavedGameSummary(Path file, String name, String course, List<String> players, LocalDateTime saved) {
    private static final DateTimeFormatter WHEN = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm");
    /** Summaries by file, kept while the file's modification time is the same (the menu asks every frame). */
    private static final Map<Path, Object[]> CACHE = new ConcurrentHashMap<>();

    /** "Meadowbrook 18, hole 5: Island Green - Ann, Bot (planner) - 2026-11-24 22:30" */
    public String label() {
        String who = players.isEmpty() ? "" : " - " + String.join(", ", players);
        String when = saved == null ? "" : " - " + saved.format(WHEN);
        return (name.equals(course) ? name : name + ": " + course) + who + when;
    }

    /** The summary of {@code file}, read once per version of the file. */
    public static SavedGameSummary cached(Path file) {
        long modified;
        try {
            modified = Files.getLastModifiedTime(file).toMillis();
        } catch (IOException e) {
            modified = -1;
        }
        Object[] hit = CACHE.get(file);
        if (hit != null && (long) hit[0] == modified) return (SavedGameSummary) hit[1];
        SavedGameSummary s = read(file);
        CACHE.put(file, new Object[]{modified, s});
        return s;
    }

    public static SavedGameSummary read(Path file) {
        String fileName = String.valueOf(file.getFileName());
        LocalDateTime saved = null;
        try {
            saved = LocalDateTime.ofInstant(Files.getLastModifiedTime(file).toInstant(), ZoneId.systemDefault());
            // Read as every save is (a regular UTF-8 file within the round's limit: a FIFO here would block the menu).
            JsonNode root = JsonFields.MAPPER.readTree(minigolf.io.TextFiles.read(file, Limits.ROUND_SAVE_FILE_BYTES));
            JsonNode game = root.path("hole").isObject() ? root.path("hole") : root; // a saved round holds its hole as a saved game
            String course = shown(game.path("course").path("name"), fileName, Limits.NAME_CHARS);
            String name = course;
            if (root.path("round").isObject()) {
                int holes = root.path("round").path("holes").size();
                int finished = root.path("scores").size(); // one row per finished hole
                name = shown(root.path("round").path("name"), fileName, Limits.NAME_CHARS) + ", hole " + Math.min(holes, finished + 1);
            }
            List<String> players = new ArrayList<>();
            for (JsonNode p : game.path("players")) {
                if (players.size() == Game.MAX_PLAYERS) break;
                players.add(shown(p.path("name"), "?", Player.MAX_NAME_LENGTH));
            }
            return new SavedGameSummary(file, name, course, List.copyOf(players), saved);
        } catch (IOException | RuntimeException e) {
            return new SavedGameSummary(file, fileName, fileName, List.of(), saved);
        }
    }

    /** A name from the file as the list shows it: the fallback when absent, cut to what a loaded save may hold. */
    private static String shown(JsonNode name, String fallback, int limit) {
        String s = name.isTextual() && !name.textValue().isBlank() ? name.textValue() : fallback;
        return s.length() <= limit ? s : s.substring(0, limit - 3) + "...";
    }
}
