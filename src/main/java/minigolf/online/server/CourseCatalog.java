package minigolf.online.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.online.Protocol;
import minigolf.physics.World;

/**
 * The courses and rounds a server offers, by name: every course file directly in its folder and in
 * {@code holes/}, every round file in {@code rounds/}, each named by its file name without
 * {@code .json} (a round wins over a course of the same name). All are loaded and checked at
 * start-up; a file that does not load is left out with one line on standard error. A single course
 * is played as a round of one hole of par {@value #COURSE_PAR}.
 */
public final class CourseCatalog {
    /** The par of a course played on its own (course files have no par). */
    public static final int COURSE_PAR = 3;

    /** A course or round the server offers. */
    public record Entry(String name, boolean isRound, Round round) {
    }

    private final Path folder;
    private final Map<String, Entry> entries;

    private CourseCatalog(Path folder, Map<String, Entry> entries) {
        this.folder = folder;
        this.entries = Collections.unmodifiableMap(entries);
    }

    /** Loads every course and round under {@code folder}. */
    public static CourseCatalog load(Path folder, java.io.PrintWriter log) {
        Map<String, Entry> entries = new LinkedHashMap<>();
        for (Path f : jsonFiles(folder.resolve("rounds"))) {
            String name = stem(f);
            try {
                entries.put(name, new Entry(name, true, RoundLoader.load(f)));
            } catch (CourseException e) {
                log.println("minigolf server: round not offered: " + e.getMessage());
            }
        }
        List<Path> courses = new ArrayList<>(jsonFiles(folder));
        courses.addAll(jsonFiles(folder.resolve("holes")));
        for (Path f : courses) {
            String name = stem(f);
            if (entries.containsKey(name)) continue;
            try {
                World world = World.load(f);
                entries.put(name, new Entry(name, false,
                        new Round(world.course().name(), List.of(new Round.Hole(f.getFileName().toString(), COURSE_PAR, world)),
                                f.toString())));
            } catch (CourseException e) {
                log.println("minigolf server: course not offered: " + e.getMessage());
            }
        }
        return new CourseCatalog(folder, entries);
    }

    private static List<Path> jsonFiles(Path dir) {
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.getFileName().toString().endsWith(".json") && Files.isRegularFile(p))
                    .filter(p -> Protocol.COURSE_NAME.matcher(stem(p)).matches()).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
    }

    private static String stem(Path f) {
        String n = f.getFileName().toString();
        return n.substring(0, n.length() - ".json".length());
    }

    /**
     * The folder a server reads by default: {@code courses/} in the working directory, else the one
     * beside the installed program's {@code lib/} folder.
     */
    public static Path defaultFolder() {
        Path here = Path.of("courses");
        if (Files.isDirectory(here)) return here.toAbsolutePath().normalize();
        try {
            Path jar = Path.of(CourseCatalog.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            if (jar.getParent() != null && jar.getParent().getParent() != null) {
                Path installed = jar.getParent().getParent().resolve("courses");
                if (Files.isDirectory(installed)) return installed;
            }
        } catch (Exception e) {
            // no code source: the working directory's folder, which does not exist
        }
        return here.toAbsolutePath().normalize();
    }

    public Path folder() {
        return folder;
    }

    /** The entry of that name, or null. */
    public Entry get(String name) {
        return entries.get(name);
    }

    public List<String> names() {
        return new ArrayList<>(entries.keySet());
    }
}
