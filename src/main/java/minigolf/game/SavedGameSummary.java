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
            if (Files.size(file) > Limits.SAVE_FILE_BYTES) return new SavedGameSummary(file, fileName, fileName, List.of(), saved);
            JsonNode root = JsonFields.MAPPER.readTree(file.toFile());
            JsonNode game = root.path("hole").isObject() ? root.path("hole") : root; // a saved round holds its hole as a saved game
            String course = game.path("course").path("name").asText(fileName);
            String name = course;
            if (root.path("round").isObject()) {
                int holes = root.path("round").path("holes").size();
                int finished = root.path("scores").size(); // one row per finished hole
                name = root.path("round").path("name").asText(fileName) + ", hole " + Math.min(holes, finished + 1);
            }
            List<String> players = new ArrayList<>();
            for (JsonNode p : game.path("players")) players.add(p.path("name").asText("?"));
            return new SavedGameSummary(file, name, course, List.copyOf(players), saved);
        } catch (IOException | RuntimeException e) {
            return new SavedGameSummary(file, fileName, fileName, List.of(), saved);
        }
    }
}
