package minigolf.classic;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import minigolf.io.TextFiles;

/**
 * Reads the original game's {@code .track} files (format V1 and V2+; see docs/classic-tracks.md).
 *
 * <p>A file is lines {@code <letter> <content>}: {@code V} version, {@code A} author, {@code N}
 * name, {@code T} map data (required); {@code C} categories (V2+; in V1 a comment), {@code I} plays,
 * strokes, best strokes and players with the best, {@code B}/{@code L} first and last best player,
 * {@code R} eleven rating counts, {@code S} six settings characters. Other lines are ignored, as the
 * original does. A V1 file takes its category from its folder's name.
 *
 * <p>Everything wrong ends in one {@link TrackFormatException}: no track is half read.
 */
public final class TrackFile {
    /** Real tracks are 1-3 KB; a file past this is not a track. */
    public static final long MAX_BYTES = 256 * 1024;
    /** Longest name or author kept: what a course name may be (the original's are under 40 characters). */
    public static final int MAX_TEXT = minigolf.course.Limits.NAME_CHARS;

    private TrackFile() {
    }

    /** Reads and parses a file; a V1 file's category comes from the name of the folder it is in. */
    public static ClassicTrack read(Path file) throws TrackFormatException {
        String source = String.valueOf(file.getFileName());
        byte[] bytes;
        try {
            bytes = TextFiles.readBytes(file, MAX_BYTES);
        } catch (IOException e) {
            throw new TrackFormatException(source + ": cannot read: " + e.getMessage());
        }
        Path parent = file.toAbsolutePath().getParent();
        Optional<TrackCategory> folder = parent == null || parent.getFileName() == null ? Optional.empty()
                : TrackCategory.ofFolder(parent.getFileName().toString());
        return parse(decode(bytes, source), source, folder);
    }

    /**
     * Parses a track's text.
     *
     * @param source         the name used in messages (the file name)
     * @param folderCategory a V1 file's category (from its folder), if any
     */
    public static ClassicTrack parse(String text, String source, Optional<TrackCategory> folderCategory)
            throws TrackFormatException {
        Integer version = null;
        String author = null, name = null, map = null, firstBest = null, settings = null;
        int mapLine = 0;
        String categoriesLine = null;
        int categoriesLineNo = 0;
        TrackStats stats = null;
        List<Integer> ratings = null;
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].endsWith("\r") ? lines[i].substring(0, lines[i].length() - 1) : lines[i];
            if (line.isBlank()) continue;
            int no = i + 1;
            char key = line.charAt(0);
            if (line.length() > 1 && line.charAt(1) != ' ') continue; // not a "<letter> " line: ignored
            String content = line.length() > 2 ? line.substring(2).trim() : "";
            switch (key) {
                case 'V' -> {
                    once(version, source, no, "V");
                    version = parseInt(content, source, no, "V", "the version");
                    if (version < 1) throw error(source, no, "V", "version " + version + " does not exist (1 or more)");
                }
                case 'A' -> {
                    once(author, source, no, "A");
                    author = text(content, source, no, "A", "the author");
                }
                case 'N' -> {
                    once(name, source, no, "N");
                    name = text(content, source, no, "N", "the name");
                }
                case 'T' -> {
                    once(map, source, no, "T");
                    map = content;
                    mapLine = no;
                }
                case 'C' -> {
                    once(categoriesLine, source, no, "C");
                    categoriesLine = content;
                    categoriesLineNo = no;
                }
                case 'I' -> {
                    once(stats, source, no, "I");
                    long[] v = numbers(content, 4, source, no, "I", "plays, strokes, best strokes, players with the best");
                    if (v[2] > Integer.MAX_VALUE) throw error(source, no, "I", "best strokes " + v[2] + " is too large");
                    stats = new TrackStats(v[0], v[1], (int) v[2], v[3]);
                }
                case 'B' -> {
                    once(firstBest, source, no, "B");
                    int comma = content.lastIndexOf(',');
                    firstBest = comma >= 0 ? content.substring(0, comma).trim() : content;
                    if (firstBest.length() > MAX_TEXT) firstBest = firstBest.substring(0, MAX_TEXT);
                }
                case 'R' -> {
                    once(ratings, source, no, "R");
                    long[] v = numbers(content, 11, source, no, "R", "eleven rating counts");
                    ratings = new ArrayList<>();
                    for (long r : v) ratings.add((int) Math.min(r, Integer.MAX_VALUE));
                }
                case 'S' -> {
                    once(settings, source, no, "S");
                    if (content.length() != 6) {
                        throw error(source, no, "S", "expected 6 settings characters, got " + content.length());
                    }
                    settings = content;
                }
                default -> {
                    // 'L' (last best player) and anything else: not needed, ignored as the original does.
                }
            }
        }
        if (version == null) throw new TrackFormatException(source + ": missing the V (version) line");
        if (author == null) throw new TrackFormatException(source + ": missing the A (author) line");
        if (name == null) throw new TrackFormatException(source + ": missing the N (name) line");
        if (map == null) throw new TrackFormatException(source + ": missing the T (map) line");
        Set<TrackCategory> categories = EnumSet.noneOf(TrackCategory.class);
        if (version >= 2) {
            if (categoriesLine != null) categories.addAll(categories(categoriesLine, source, categoriesLineNo));
        } else {
            folderCategory.ifPresent(categories::add);
        }
        if (stats != null && stats.plays() > 0 && stats.bestStrokes() < 1) {
            throw new TrackFormatException(source + ": I: best strokes " + stats.bestStrokes()
                    + " for " + stats.plays() + " plays (must be at least 1)");
        }
        TileMap tiles;
        int comma = map.indexOf(',');
        String data = comma >= 0 ? map.substring(0, comma) : map; // ",Ads:..." places adverts: not ours
        try {
            tiles = TileMapDecoder.decode(data);
        } catch (IllegalArgumentException e) {
            throw error(source, mapLine, "T", e.getMessage());
        }
        return new ClassicTrack(version, author, name, categories, stats, firstBest, ratings,
                settings == null ? ClassicTrack.DEFAULT_SETTINGS : settings, tiles);
    }

    /** UTF-8, or Latin-1 for the older files written that way (author names with ä, ö). */
    static String decode(byte[] bytes, String source) throws TrackFormatException {
        for (byte b : bytes) {
            if (b == 0) throw new TrackFormatException(source + ": not a track file: binary data");
        }
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            return new String(bytes, StandardCharsets.ISO_8859_1);
        }
    }

    private static Set<TrackCategory> categories(String content, String source, int no) throws TrackFormatException {
        Set<TrackCategory> set = EnumSet.noneOf(TrackCategory.class);
        if (content.isEmpty()) return set;
        for (String part : content.split(",")) {
            int id = parseInt(part.trim(), source, no, "C", "a category id");
            if (id == 0) continue; // "all": no category of its own
            set.add(TrackCategory.ofId(id).orElseThrow(() -> error(source, no, "C",
                    "category " + id + " does not exist (1 basic, 2 traditional, 3 modern, 4 hio, 5 short, 6 long)")));
        }
        return set;
    }

    private static void once(Object seen, String source, int no, String key) throws TrackFormatException {
        if (seen != null) throw error(source, no, key, "a second " + key + " line");
    }

    private static String text(String content, String source, int no, String key, String what) throws TrackFormatException {
        if (content.isEmpty()) throw error(source, no, key, what + " is empty");
        if (content.length() > MAX_TEXT) {
            throw error(source, no, key, what + " is " + content.length() + " characters long (the limit is " + MAX_TEXT + ")");
        }
        for (int i = 0; i < content.length(); i++) {
            if (Character.isISOControl(content.charAt(i))) throw error(source, no, key, what + " holds a control character");
        }
        return content;
    }

    private static int parseInt(String s, String source, int no, String key, String what) throws TrackFormatException {
        long v = parseLong(s, source, no, key, what);
        if (v > Integer.MAX_VALUE) throw error(source, no, key, what + " " + s + " is too large");
        return (int) v;
    }

    private static long parseLong(String s, String source, int no, String key, String what) throws TrackFormatException {
        if (s.isEmpty() || s.length() > 18 || !s.chars().allMatch(ch -> ch >= '0' && ch <= '9')) {
            throw error(source, no, key, what + " is not a whole number >= 0");
        }
        return Long.parseLong(s);
    }

    private static long[] numbers(String content, int count, String source, int no, String key, String what)
            throws TrackFormatException {
        String[] parts = content.split(",", -1);
        if (parts.length != count) {
            throw error(source, no, key, "expected " + count + " numbers (" + what + "), got " + parts.length);
        }
        long[] v = new long[count];
        for (int i = 0; i < count; i++) v[i] = parseLong(parts[i].trim(), source, no, key, "number " + (i + 1));
        return v;
    }

    private static TrackFormatException error(String source, int line, String key, String problem) {
        return new TrackFormatException(source + ": line " + line + " (" + key + "): " + problem);
    }
}
