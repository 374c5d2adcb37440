package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.course.CourseLoader;
import minigolf.game.RoundLoader;
import minigolf.game.SettingsStore;

/**
 * Where courses are found: {@code courses/} in the working directory, {@code courses/} beside the
 * installed game's {@code lib/} folder, and the player's own in {@code <config>/courses}. Files
 * that do not load are left out of the list.
 */
final class CourseFolders {
    private CourseFolders() {
    }

    /** A course offered: its name, its file, and whether it is the player's own. */
    record CourseEntry(String name, Path file, boolean own) {
    }

    /** A round offered, loaded so that it can be played. */
    record RoundEntry(minigolf.game.Round round, Path file) {
    }

    /**
     * The rounds in {@code rounds/} beside the shipped courses, then those in {@code <config>/rounds},
     * each group in the order a player reads them: the shorter rounds first, then by name ("Meadowbrook
     * Front Nine", then "Frostkeep", "Gull Bay", ...), not by file name. Rounds that do not load are left out.
     */
    static List<RoundEntry> rounds(SettingsStore store) {
        List<RoundEntry> all = roundFiles(store);
        Path own = store.directory().resolve("rounds").toAbsolutePath().normalize();
        List<RoundEntry> out = new ArrayList<>(all.stream().filter(r -> !r.file().toAbsolutePath().normalize().startsWith(own))
                .sorted(PLAYER_ORDER).toList());
        out.addAll(all.stream().filter(r -> r.file().toAbsolutePath().normalize().startsWith(own)).sorted(PLAYER_ORDER).toList());
        return out;
    }

    /** Shorter rounds first, then by name (case aside). */
    private static final Comparator<RoundEntry> PLAYER_ORDER = Comparator.<RoundEntry>comparingInt(r -> r.round().size())
            .thenComparing(r -> r.round().name(), String.CASE_INSENSITIVE_ORDER);

    private static List<RoundEntry> roundFiles(SettingsStore store) {
        List<Path> dirs = new ArrayList<>();
        for (Path d : shippedFolders()) dirs.add(d.resolve("rounds"));
        dirs.add(store.directory().resolve("rounds"));
        List<RoundEntry> out = new ArrayList<>();
        Set<Path> seen = new LinkedHashSet<>();
        for (Path dir : dirs) {
            if (!Files.isDirectory(dir)) continue;
            try (Stream<Path> files = Files.list(dir)) {
                for (Path f : files.filter(p -> p.toString().endsWith(".json")).sorted().toList()) {
                    try {
                        if (seen.add(f.getFileName())) out.add(new RoundEntry(RoundLoader.load(f), f));
                    } catch (CourseException e) {
                        System.err.println("minigolf: round not offered: " + e.getMessage());
                    }
                }
            } catch (IOException e) {
                // an unreadable folder offers nothing
            }
        }
        return out;
    }

    private static Set<Path> shippedFolders() {
        Set<Path> shipped = new LinkedHashSet<>();
        shipped.add(Path.of("courses").toAbsolutePath().normalize());
        try {
            Path jar = Path.of(CourseFolders.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            if (jar.getParent() != null && jar.getParent().getParent() != null) {
                shipped.add(jar.getParent().getParent().resolve("courses").toAbsolutePath().normalize());
            }
        } catch (Exception e) {
            // no code source (unusual class loader): the working directory's courses only
        }
        return shipped;
    }

    /** Where the classic tracks are read from: the settings' folder, else {@code <config>/classic}. */
    static Path classicFolder(SettingsStore store, minigolf.game.UserSettings settings) {
        String own = settings.classicFolder();
        if (!own.isBlank()) {
            try {
                return Path.of(own.strip());
            } catch (java.nio.file.InvalidPathException e) {
                // not a path on this system: the default
            }
        }
        return store.directory().resolve("classic");
    }

    /**
     * The single holes offered for practice: every hole of the rounds, in their order (each file
     * once), the practice holes of the course elements ({@code courses/practice/}), then the
     * player's own courses. The loose courses beside the rounds are the engine's
     * test terrains (a plane, sine hills, a 256 x 256 grid, 200 obstacles): {@code minigolf play
     * FILE} plays them, a player's list does not offer them.
     */
    static List<CourseEntry> list(SettingsStore store) {
        List<CourseEntry> out = new ArrayList<>();
        Set<Path> seen = new LinkedHashSet<>();
        for (RoundEntry r : rounds(store)) {
            Path folder = r.file().toAbsolutePath().getParent();
            for (int i = 0; i < r.round().size(); i++) {
                Path f = folder.resolve(r.round().hole(i).course()).normalize();
                if (!seen.add(f)) continue;
                try {
                    out.add(new CourseEntry(CourseLoader.load(f).name(), f, false));
                } catch (CourseException e) {
                    // a hole that does not load is not offered (its round says why when played)
                }
            }
        }
        // The practice holes, one course element each (docs/course-format.md, "Practice holes").
        Set<Path> practice = new LinkedHashSet<>();
        for (Path dir : shippedFolders()) add(dir.resolve(PRACTICE), false, out, practice, PRACTICE);
        add(store.directory().resolve("courses"), true, out, new LinkedHashSet<>(), null);
        return out;
    }

    /** The shipped courses' folder of practice holes. */
    static final String PRACTICE = "practice";

    /** Adds the courses of {@code dir}; a file name seen already (under the same {@code folder}) is offered once. */
    private static void add(Path dir, boolean own, List<CourseEntry> out, Set<Path> seen, String folder) {
        if (!Files.isDirectory(dir)) return;
        try (Stream<Path> files = Files.list(dir)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".json")).sorted().toList()) {
                try {
                    String name = CourseLoader.load(f).name();
                    Path key = folder == null ? f.getFileName() : Path.of(folder).resolve(f.getFileName());
                    if (seen.add(key)) out.add(new CourseEntry(name, f, own));
                } catch (CourseException e) {
                    // not a loadable course: not offered
                }
            }
        } catch (IOException e) {
            // an unreadable folder offers nothing
        }
    }
}
