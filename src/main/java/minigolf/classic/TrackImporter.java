package minigolf.classic;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileVisitOption;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.course.CourseWriter;
import minigolf.io.AtomicFile;

/**
 * {@code minigolf import-tracks}: every {@code .track} file under a folder becomes a course folder
 * ({@code <out>/<name>/course.json} and its wall models) and a line of {@code <out>/index.json}
 * (docs/classic-tracks.md). A track filed under two category folders (V1) is imported once with
 * both categories. A track that cannot be imported writes nothing and is listed with its reason.
 */
public final class TrackImporter {
    public static final String INDEX = "index.json";
    public static final String COURSE = "course.json";
    /** The folder under the output that holds one folder per track (a suite for {@code experiment}). */
    public static final String COURSES = "courses";
    /** Most .track files read from one folder. */
    public static final int MAX_FILES = 20_000;
    static final int MAX_DEPTH = 8;

    /** One imported track: where its course is (relative to the output folder) and what the file says. */
    public record Entry(ClassicTrack track, String course, List<String> sources, List<String> notes) {
    }

    /** A file that was not imported, and why (one line). */
    public record Failure(String source, String reason) {
    }

    public record Result(List<Entry> imported, List<Failure> failed, String shapes) {
    }

    private TrackImporter() {
    }

    /** The .track files under {@code dir} (or {@code dir} itself if it is one), in path order. */
    public static List<Path> trackFiles(Path dir) throws IOException {
        if (Files.isRegularFile(dir)) return List.of(dir);
        if (!Files.isDirectory(dir)) throw new IOException(dir + ": no such folder");
        try (Stream<Path> walk = Files.walk(dir, MAX_DEPTH, new FileVisitOption[0])) {
            List<Path> files = walk.filter(p -> p.getFileName() != null
                            && p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".track"))
                    .filter(Files::isRegularFile).sorted().limit(MAX_FILES + 1L).toList();
            if (files.size() > MAX_FILES) throw new IOException(dir + ": more than " + MAX_FILES + " .track files");
            return files;
        }
    }

    /**
     * Imports every track under {@code dir} into {@code out}.
     *
     * @param masks the shapes to draw the tiles with (from the user's images, or the built-in approximation)
     */
    public static Result run(Path dir, Path out, ShapeMasks masks, ClassicScale scale) throws IOException {
        List<Path> files = trackFiles(dir);
        Path base = Files.isDirectory(dir) ? dir : dir.getParent();
        // Parse all, merging the copies V1 keeps of a track in each of its categories.
        Map<String, ClassicTrack> tracks = new LinkedHashMap<>();
        Map<String, List<String>> sources = new LinkedHashMap<>();
        List<Failure> failed = new ArrayList<>();
        for (Path f : files) {
            String source = base == null ? f.toString() : base.relativize(f).toString();
            ClassicTrack t;
            try {
                t = TrackFile.read(f);
            } catch (TrackFormatException e) {
                String m = e.getMessage(), prefix = f.getFileName() + ": ";
                failed.add(new Failure(source, m.startsWith(prefix) ? m.substring(prefix.length()) : m));
                continue;
            }
            String key = t.author() + "\n" + t.name() + "\n" + t.tiles().hashCode();
            ClassicTrack seen = tracks.get(key);
            if (seen != null && seen.tiles().equals(t.tiles())) {
                Set<TrackCategory> both = EnumSet.noneOf(TrackCategory.class);
                both.addAll(seen.categories());
                both.addAll(t.categories());
                tracks.put(key, new ClassicTrack(seen.version(), seen.author(), seen.name(), both, seen.stats(),
                        seen.firstBest(), seen.ratings(), seen.settings(), seen.tiles()));
                sources.get(key).add(source);
            } else {
                tracks.put(key + (seen != null ? "\n" + source : ""), t);
                sources.put(key + (seen != null ? "\n" + source : ""), new ArrayList<>(List.of(source)));
            }
        }
        Files.createDirectories(out);
        List<Entry> imported = new ArrayList<>();
        Set<String> names = new java.util.HashSet<>();
        for (Map.Entry<String, ClassicTrack> e : tracks.entrySet()) {
            ClassicTrack t = e.getValue();
            List<String> from = sources.get(e.getKey());
            TrackConverter.Converted c;
            try {
                c = TrackConverter.convert(t, masks, scale);
            } catch (TrackFormatException ex) {
                failed.add(new Failure(from.get(0), ex.getMessage()));  // "<name>: ..."
                continue;
            }
            String folder = uniqueFolder(t, names);
            Path target = out.resolve(COURSES).resolve(folder);
            Files.createDirectories(target);
            clearOld(target);
            try {
                // The models first (plain writes: the course, written last and atomically, is what
                // makes the folder a course), then the course, which saving checks loads.
                for (Map.Entry<String, String> file : c.files().entrySet()) {
                    Files.writeString(target.resolve(file.getKey()), file.getValue(), StandardCharsets.UTF_8);
                }
                CourseWriter.save(c.course(), target.resolve(COURSE));
            } catch (CourseException ex) {
                clearOld(target);
                deleteIfEmpty(target);
                names.remove(folder.toLowerCase(Locale.ROOT));
                failed.add(new Failure(from.get(0), t.name() + ": " + ex.detail()));
                continue;
            }
            imported.add(new Entry(t, COURSES + "/" + folder + "/" + COURSE, List.copyOf(from), c.notes()));
        }
        Result result = new Result(List.copyOf(imported), List.copyOf(failed), masks.source());
        AtomicFile.write(out.resolve(INDEX), index(result, scale).getBytes(StandardCharsets.UTF_8));
        return result;
    }

    /** Removes what an earlier import wrote in a track's folder (the course, its models and materials). */
    private static void clearOld(Path folder) throws IOException {
        try (var files = Files.list(folder)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                String n = f.getFileName().toString();
                if (Files.isRegularFile(f) && (n.equals(COURSE) || n.endsWith(".obj") || n.endsWith(".mtl"))) {
                    Files.delete(f);
                }
            }
        }
    }

    private static void deleteIfEmpty(Path folder) throws IOException {
        try (var files = Files.list(folder)) {
            if (files.findAny().isEmpty()) Files.delete(folder);
        }
    }

    /** A folder name from the author and name: letters, digits, '-' and '_' only; unique. */
    static String uniqueFolder(ClassicTrack t, Set<String> taken) {
        String raw = t.author() + "-" + t.name();
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < raw.length() && sb.length() < 80; i++) {
            char c = raw.charAt(i);
            sb.append(c < 128 && (Character.isLetterOrDigit(c) || c == '-' || c == '_') ? c : '_');
        }
        String base = sb.toString(), name = base;
        for (int k = 2; !taken.add(name.toLowerCase(Locale.ROOT)); k++) name = base + "-" + k;
        return name;
    }

    /** The index: every track with its human statistics, and the files that failed. */
    static String index(Result r, ClassicScale scale) throws IOException {
        ObjectMapper json = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        ObjectNode root = json.createObjectNode();
        root.put("format", 1);
        root.put("shapes", r.shapes());
        root.put("tileMetres", scale.tile());
        ArrayNode list = root.putArray("tracks");
        for (Entry e : r.imported()) {
            ClassicTrack t = e.track();
            ObjectNode o = list.addObject();
            o.put("name", t.name());
            o.put("author", t.author());
            ArrayNode cats = o.putArray("categories");
            for (TrackCategory c : TrackCategory.values()) if (t.categories().contains(c)) cats.add(c.folder());
            TrackStats s = t.stats();
            if (s != null) {
                o.put("plays", s.plays());
                o.put("strokes", s.strokes());
                if (s.plays() > 0) o.put("averageStrokes", s.averageStrokes());
                o.put("bestStrokes", s.bestStrokes());
                o.put("playersWithBest", s.bestPlayers());
            }
            o.put("course", e.course());
            ArrayNode src = o.putArray("sources");
            e.sources().forEach(src::add);
            ArrayNode notes = o.putArray("notes");
            e.notes().forEach(notes::add);
        }
        ArrayNode failed = root.putArray("failed");
        for (Failure f : r.failed()) {
            ObjectNode o = failed.addObject();
            o.put("source", f.source());
            o.put("reason", f.reason());
        }
        return json.writeValueAsString(root) + "\n";
    }
}
