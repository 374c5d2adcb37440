package minigolf.classic;

import java.util.Locale;
import java.util.Optional;

/**
 * The original game's track categories: the id a V2 file lists on its {@code C} line and the
 * folder name a V1 file is filed under.
 */
public enum TrackCategory {
    BASIC(1, "basic"),
    TRADITIONAL(2, "traditional"),
    MODERN(3, "modern"),
    HOLE_IN_ONE(4, "hio"),
    SHORT(5, "short"),
    LONG(6, "long");

    private final int id;
    private final String folder;

    TrackCategory(int id, String folder) {
        this.id = id;
        this.folder = folder;
    }

    public int id() {
        return id;
    }

    /** The folder name of V1 files and the name written in the index. */
    public String folder() {
        return folder;
    }

    public static Optional<TrackCategory> ofId(int id) {
        for (TrackCategory c : values()) {
            if (c.id == id) return Optional.of(c);
        }
        return Optional.empty();
    }

    /** The category a V1 file's folder names, case-insensitively. */
    public static Optional<TrackCategory> ofFolder(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        for (TrackCategory c : values()) {
            if (c.folder.equals(lower)) return Optional.of(c);
        }
        return Optional.empty();
    }
}
