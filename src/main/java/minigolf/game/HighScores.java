package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import minigolf.io.AtomicFile;

/**
 * Scores kept between games, per round (by the round's name): a high-score table of the best
 * {@link #TABLE_SIZE} complete rounds (name, score, date), and every player's personal best for the
 * round and for each of its holes. Stored as {@code scores.json} in the user's config folder,
 * written atomically ({@link AtomicFile}); a broken file is reported in one line and not
 * overwritten until the player's next score replaces it.
 */
public final class HighScores {
    public static final int FORMAT = 1;
    public static final int TABLE_SIZE = 10;
    static final String KIND = "minigolf-high-scores";

    /** A line of a round's table. */
    public record Entry(String name, int score, LocalDate date) {
    }

    /** The best score someone has, and who (the course list shows it). */
    public record Best(String name, int score) {
    }

    /** The key single-course games are kept under: a one-hole "round" of the course's name. */
    public static String practiceKey(String courseName) {
        return "practice: " + courseName;
    }

    /** The achievement of a hole played in one stroke. */
    public static final String HOLE_IN_ONE = "hole in one!";

    /** What a finished round or hole achieved, for the player's message. */
    public record Achievement(String name, String what) {
    }

    private static final class RoundScores {
        final List<Entry> table = new ArrayList<>();
        final Map<String, Integer> bestRound = new LinkedHashMap<>();
        final Map<String, Map<Integer, Integer>> bestHoles = new LinkedHashMap<>();
    }

    private final Map<String, RoundScores> rounds = new LinkedHashMap<>();

    /** The file in a config folder. */
    public static Path file(Path configDirectory) {
        return configDirectory.resolve("scores.json");
    }

    /** Loads the scores; no file means none yet. */
    public static HighScores load(Path file) throws SaveGameException {
        HighScores h = new HighScores();
        if (!Files.exists(file)) return h;
        String source = String.valueOf(file);
        JsonFields f = new JsonFields(source);
        JsonNode root = f.parse(JsonFields.readText(file, minigolf.course.Limits.SCORES_FILE_BYTES));
        f.onlyFields(root, null, List.of("format", "kind", "rounds"));
        int format = f.integer(root, null, "format", 0, Integer.MAX_VALUE);
        if (format != FORMAT) throw f.error("format", "this game reads score files of format " + FORMAT + ", got " + format);
        if (!KIND.equals(f.text(root, null, "kind"))) throw f.error("kind", "must be \"" + KIND + "\"");
        JsonNode rs = f.object(f.field(root, null, "rounds"), "rounds");
        for (Iterator<Map.Entry<String, JsonNode>> it = rs.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            String p = "rounds." + e.getKey();
            f.shortText(e.getKey(), "rounds", minigolf.course.Limits.NAME_CHARS);
            JsonNode r = f.object(e.getValue(), p);
            f.onlyFields(r, p, List.of("table", "players"));
            RoundScores scores = new RoundScores();
            JsonNode table = f.array(r, p, "table");
            for (int i = 0; i < table.size(); i++) {
                String q = p + ".table[" + i + "]";
                JsonNode t = f.object(table.get(i), q);
                f.onlyFields(t, q, List.of("name", "score", "date"));
                String name = f.shortText(f.text(t, q, "name"), q + ".name", Player.MAX_NAME_LENGTH);
                scores.table.add(new Entry(name, f.integer(t, q, "score", 1, 100_000), date(f, t, q)));
            }
            JsonNode players = f.object(f.field(r, p, "players"), p + ".players");
            for (Iterator<Map.Entry<String, JsonNode>> pit = players.fields(); pit.hasNext(); ) {
                Map.Entry<String, JsonNode> pe = pit.next();
                String q = p + ".players." + pe.getKey();
                f.shortText(pe.getKey(), p + ".players", Player.MAX_NAME_LENGTH);
                JsonNode pl = f.object(pe.getValue(), q);
                f.onlyFields(pl, q, List.of("round", "holes"));
                if (pl.has("round")) scores.bestRound.put(pe.getKey(), f.integer(pl, q, "round", 1, 100_000));
                JsonNode holes = f.array(pl, q, "holes");
                Map<Integer, Integer> best = new LinkedHashMap<>();
                for (int i = 0; i < holes.size(); i++) {
                    if (holes.get(i).isNull()) continue;
                    if (!holes.get(i).isIntegralNumber() || holes.get(i).intValue() < 1) {
                        throw f.error(q + ".holes[" + i + "]", "must be a whole number >= 1 or null");
                    }
                    best.put(i, holes.get(i).intValue());
                }
                scores.bestHoles.put(pe.getKey(), best);
            }
            h.rounds.put(e.getKey(), scores);
        }
        return h;
    }

    private static LocalDate date(JsonFields f, JsonNode t, String path) throws SaveGameException {
        String d = f.text(t, path, "date");
        try {
            return LocalDate.parse(d);
        } catch (DateTimeParseException e) {
            throw f.error(path + ".date", "must be a date like 2026-11-24, got \"" + d + "\"");
        }
    }

    public void save(Path file) throws SaveGameException {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            AtomicFile.write(file, toJson().getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new SaveGameException(String.valueOf(file), null, "cannot save: " + e.getMessage(), e);
        }
    }

    String toJson() {
        ObjectNode root = JsonFields.MAPPER.createObjectNode();
        root.put("format", FORMAT);
        root.put("kind", KIND);
        ObjectNode rs = root.putObject("rounds");
        for (Map.Entry<String, RoundScores> e : rounds.entrySet()) {
            ObjectNode r = rs.putObject(e.getKey());
            ArrayNode table = r.putArray("table");
            for (Entry t : e.getValue().table) {
                table.addObject().put("name", t.name()).put("score", t.score()).put("date", t.date().toString());
            }
            ObjectNode players = r.putObject("players");
            java.util.Set<String> names = new java.util.LinkedHashSet<>(e.getValue().bestRound.keySet());
            names.addAll(e.getValue().bestHoles.keySet());
            for (String n : names) {
                ObjectNode p = players.putObject(n);
                Integer best = e.getValue().bestRound.get(n);
                if (best != null) p.put("round", best);
                ArrayNode holes = p.putArray("holes");
                Map<Integer, Integer> bh = e.getValue().bestHoles.getOrDefault(n, Map.of());
                int last = bh.keySet().stream().mapToInt(Integer::intValue).max().orElse(-1);
                for (int i = 0; i <= last; i++) {
                    if (bh.containsKey(i)) holes.add(bh.get(i));
                    else holes.addNull();
                }
            }
        }
        try {
            return JsonFields.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n";
        } catch (IOException e) {
            throw new IllegalStateException("cannot write JSON", e);
        }
    }

    /** The round's table, best first (equal scores: the earlier date first, then the earlier entry). */
    public List<Entry> table(String round) {
        RoundScores r = rounds.get(round);
        return r == null ? List.of() : List.copyOf(r.table);
    }

    /** A player's best complete round, or null. */
    public Integer personalBest(String round, String name) {
        RoundScores r = rounds.get(round);
        return r == null ? null : r.bestRound.get(name);
    }

    /** A player's best score on a hole of the round (0-based), or null. */
    public Integer personalBest(String round, int hole, String name) {
        RoundScores r = rounds.get(round);
        return r == null ? null : r.bestHoles.getOrDefault(name, Map.of()).get(hole);
    }

    /** The best complete round anyone played (the table's first line), or null. */
    public Best bestRound(String round) {
        RoundScores r = rounds.get(round);
        return r == null || r.table.isEmpty() ? null : new Best(r.table.get(0).name(), r.table.get(0).score());
    }

    /** The best score anyone has on a hole of the round (0-based; the first who reached it on equal scores), or null. */
    public Best bestOnHole(String round, int hole) {
        RoundScores r = rounds.get(round);
        if (r == null) return null;
        Best best = null;
        for (Map.Entry<String, Map<Integer, Integer>> e : r.bestHoles.entrySet()) {
            Integer s = e.getValue().get(hole);
            if (s != null && (best == null || s < best.score())) best = new Best(e.getKey(), s);
        }
        return best;
    }

    /** Records a finished hole's scores (by seat); returns the new personal bests and holes in one. */
    public List<Achievement> recordHole(String round, int hole, List<Player> players, int[] scores) {
        RoundScores r = rounds.computeIfAbsent(round, k -> new RoundScores());
        List<Achievement> out = new ArrayList<>();
        for (int s = 0; s < players.size(); s++) {
            String n = players.get(s).name();
            Map<Integer, Integer> best = r.bestHoles.computeIfAbsent(n, k -> new LinkedHashMap<>());
            Integer old = best.get(hole);
            if (scores[s] == 1) out.add(new Achievement(n, HOLE_IN_ONE));
            if (old == null || scores[s] < old) {
                best.put(hole, scores[s]);
                if (old != null) out.add(new Achievement(n, "personal best on hole " + (hole + 1) + " (" + scores[s] + ", was " + old + ")"));
            }
        }
        return out;
    }

    /** Records a complete round's totals; returns new personal bests and places in the table. */
    public List<Achievement> recordRound(String round, RoundScorecard card, List<Player> players, LocalDate date) {
        RoundScores r = rounds.computeIfAbsent(round, k -> new RoundScores());
        List<Achievement> out = new ArrayList<>();
        for (int s = 0; s < players.size(); s++) {
            String n = players.get(s).name();
            int total = card.rows().get(s).total();
            Integer old = r.bestRound.get(n);
            if (old == null || total < old) {
                r.bestRound.put(n, total);
                out.add(new Achievement(n, old == null ? "first round " + total : "personal best round " + total + " (was " + old + ")"));
            }
            Entry e = new Entry(n, total, date);
            r.table.add(e);
            r.table.sort(Comparator.comparingInt(Entry::score).thenComparing(Entry::date));
            int place = r.table.indexOf(e);
            while (r.table.size() > TABLE_SIZE) r.table.remove(r.table.size() - 1);
            if (place < TABLE_SIZE) out.add(new Achievement(n, "high score #" + (place + 1)));
        }
        return out;
    }
}
