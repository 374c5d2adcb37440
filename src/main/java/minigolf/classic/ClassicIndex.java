package minigolf.classic;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import com.fasterxml.jackson.databind.ObjectMapper;
import minigolf.io.TextFiles;

/**
 * The index {@code import-tracks} writes ({@code index.json}, docs/classic-tracks.md), read back:
 * what the game's "Classic tracks" list and {@code classic-report} show. Entries whose course file
 * would lie outside the folder (or that names no path) are left out.
 */
public final class ClassicIndex {
    /** Largest index read (2,000 tracks take about 1 MB). */
    public static final long MAX_BYTES = 16L << 20;

    private ClassicIndex() {
    }

    /**
     * A track of the index.
     *
     * @param averageStrokes the human average, NaN where the file had no statistics
     * @param bestStrokes    the best human score, 0 where unknown
     * @param folder         the course's folder name (an experiment's course name)
     */
    public record Entry(String name, String author, List<String> categories, long plays, double averageStrokes,
                        int bestStrokes, long playersWithBest, Path course, String folder) {
        public Entry {
            categories = List.copyOf(categories);
        }

        /** Whether the name or author contains {@code text} (any case) and {@code category} is one of its categories (null: any). */
        public boolean matches(String text, String category) {
            String t = text == null ? "" : text.strip().toLowerCase(Locale.ROOT);
            boolean textOk = t.isEmpty() || name.toLowerCase(Locale.ROOT).contains(t) || author.toLowerCase(Locale.ROOT).contains(t);
            return textOk && (category == null || categories.contains(category));
        }
    }

    /** The index of an import and the files that failed. */
    public record Index(List<Entry> tracks, List<String> failed) {
    }

    /** Reads {@code <folder>/index.json}. */
    public static Index read(Path folder) throws IOException {
        Path file = folder.resolve(TrackImporter.INDEX);
        JsonNode root;
        try {
            root = new ObjectMapper().readTree(TextFiles.read(file, MAX_BYTES));
        } catch (TextFiles.TextFileException e) {
            throw new IOException(file + ": cannot read: " + e.getMessage(), e);
        } catch (IOException e) {
            throw new IOException(file + ": not valid JSON: " + e.getMessage().lines().findFirst().orElse(""), e);
        }
        if (root == null || !root.path("tracks").isArray()) throw new IOException(file + ": not an import-tracks index");
        Path base = folder.toAbsolutePath().normalize();
        List<Entry> tracks = new ArrayList<>();
        for (JsonNode t : root.get("tracks")) {
            Path path = courseIn(base, t.path("course").asText(""));
            if (path == null) continue;
            List<String> categories = new ArrayList<>();
            for (JsonNode c : t.path("categories")) categories.add(c.asText());
            tracks.add(new Entry(cut(t.path("name").asText("?")), cut(t.path("author").asText("?")), categories,
                    t.path("plays").asLong(0), t.has("averageStrokes") ? t.get("averageStrokes").asDouble() : Double.NaN,
                    t.path("bestStrokes").asInt(0), t.path("playersWithBest").asLong(0), path,
                    path.getParent().getFileName().toString()));
        }
        List<String> failed = new ArrayList<>();
        for (JsonNode f : root.path("failed")) failed.add(f.path("source").asText() + ": " + f.path("reason").asText());
        return new Index(List.copyOf(tracks), List.copyOf(failed));
    }

    /** The course's path inside {@code base}, or null where it would lie outside or is no path (a NUL character). */
    private static Path courseIn(Path base, String course) {
        if (course.isEmpty()) return null;
        try {
            Path path = base.resolve(course).normalize();
            return path.startsWith(base) && path.getParent() != null ? path : null;
        } catch (InvalidPathException e) {
            return null;
        }
    }

    /** Longest name or author shown (the tracks' are under 40 characters). */
    static final int NAME_CHARS = 128;

    private static String cut(String s) {
        return s.length() <= NAME_CHARS ? s : s.substring(0, NAME_CHARS);
    }
}
