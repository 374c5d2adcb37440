package minigolf.editor;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Where "Save as" suggests saving: the course's own file when it has one, else the player's courses
 * folder ({@code <config>/courses}, which the game's "Select course" lists) under a file name made
 * from the course's name, numbered when that file exists already.
 */
public final class SaveLocation {
    private SaveLocation() {
    }

    public static Path suggest(Path configDir, Path current, String courseName) {
        if (current != null) return current;
        Path dir = configDir.resolve("courses");
        String stem = stem(courseName);
        Path p = dir.resolve(stem + ".json");
        for (int n = 2; Files.exists(p); n++) p = dir.resolve(stem + "-" + n + ".json");
        return p;
    }

    /** "Windy Hill #2" -> "windy-hill-2"; "my-course" when nothing is left. */
    static String stem(String name) {
        String s = name == null ? "" : name.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9]+", "-").replaceAll("^-+|-+$", "");
        if (s.length() > 40) s = s.substring(0, 40).replaceAll("-+$", "");
        return s.isEmpty() ? "my-course" : s;
    }
}
