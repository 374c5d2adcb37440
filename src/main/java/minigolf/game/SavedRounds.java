package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.course.CourseException;
import minigolf.io.AtomicFile;
import minigolf.physics.World;

/**
 * Saves a round in progress and loads it back. Like a saved game ({@link SavedGames}) the file
 * embeds every hole's course, so it resumes exactly even if the round's files changed; the current
 * hole is a complete saved game (its balls, counts and shots) under {@code "hole"}. Written
 * atomically ({@link AtomicFile}); reading checks every field and fails with one line.
 */
public final class SavedRounds {
    public static final int FORMAT = 1;
    static final String KIND = "minigolf-saved-round";
    private static final List<String> TOP = List.of("format", "kind", "round", "scores", "strokes", "hole");
    private static final List<String> ROUND = List.of("name", "source", "holes");
    private static final List<String> HOLE = List.of("course", "par", "definition");

    private SavedRounds() {
    }

    public static void save(RoundGame round, Path file) throws SaveGameException {
        try {
            AtomicFile.write(file, toJson(round).getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new SaveGameException(String.valueOf(file), null, e.getMessage(), e);
        }
    }

    /** What a save file holds: a round (then {@code game} is null) or a single game (then {@code round} is null). */
    public record AnySave(RoundGame round, SavedGames.Loaded game) {
    }

    /** A saved round or a saved game, whichever the file holds, read once (within the larger, round's, limit). */
    public static AnySave loadAny(Path file) throws SaveGameException {
        String text = JsonFields.readText(file, minigolf.course.Limits.ROUND_SAVE_FILE_BYTES);
        String source = String.valueOf(file);
        return isSavedRound(text) ? new AnySave(parse(text, source), null) : new AnySave(null, SavedGames.parse(text, source));
    }

    public static RoundGame load(Path file) throws SaveGameException {
        return parse(JsonFields.readText(file, minigolf.course.Limits.ROUND_SAVE_FILE_BYTES), String.valueOf(file));
    }

    /** True if the file looks like a saved round (its "kind"), without checking the rest. */
    public static boolean isSavedRound(String json) {
        try {
            JsonNode root = JsonFields.MAPPER.readTree(json);
            return root != null && root.isObject() && KIND.equals(root.path("kind").asText());
        } catch (IOException e) {
            return false;
        }
    }

    public static String toJson(RoundGame rg) {
        ObjectNode root = JsonFields.MAPPER.createObjectNode();
        root.put("format", FORMAT);
        root.put("kind", KIND);
        ObjectNode round = root.putObject("round");
        round.put("name", rg.round().name());
        round.put("source", rg.round().source());
        ArrayNode holes = round.putArray("holes");
        try {
            for (Round.Hole h : rg.round().holes()) {
                ObjectNode o = holes.addObject();
                o.put("course", h.course());
                o.put("par", h.par());
                o.set("definition", CourseTrees.of(h.world()));
            }
            ArrayNode scores = root.putArray("scores");
            for (int[] row : rg.finishedScores()) {
                ArrayNode r = scores.addArray();
                for (int s : row) r.add(s);
            }
            // Every finished hole's strokes, so that any hole of a saved round can be watched again.
            ArrayNode strokes = root.putArray("strokes");
            for (int h = 0; h < rg.holesFinished(); h++) SavedGames.writeHistory(strokes.addArray(), rg.holeStrokes(h));
            root.set("hole", SavedGames.tree(rg.game()));
            return JsonFields.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n";
        } catch (IOException e) {
            throw new IllegalStateException("cannot write JSON", e);
        }
    }

    public static RoundGame parse(String json, String source) throws SaveGameException {
        return parse(json, source, World::parse);
    }

    /** How a hole's course definition becomes a world (online play shares one world per definition among rooms). */
    @FunctionalInterface
    public interface WorldReader {
        World read(String json, String source) throws CourseException;
    }

    /** As {@link #parse(String, String)}, every hole's definition read by {@code worlds}. */
    public static RoundGame parse(String json, String source, WorldReader worlds) throws SaveGameException {
        JsonFields f = new JsonFields(source);
        JsonNode root = f.parse(json);
        f.onlyFields(root, null, TOP);
        int format = f.integer(root, null, "format", 0, Integer.MAX_VALUE);
        if (format != FORMAT) throw f.error("format", "this game reads saved rounds of format " + FORMAT + ", got " + format);
        if (!KIND.equals(f.text(root, null, "kind"))) throw f.error("kind", "must be \"" + KIND + "\" (is this a saved round?)");
        JsonNode roundNode = f.object(f.field(root, null, "round"), "round");
        f.onlyFields(roundNode, "round", ROUND);
        String name = f.text(roundNode, "round", "name");
        String roundSource = f.text(roundNode, "round", "source");
        JsonNode holesNode = f.array(roundNode, "round", "holes");
        if (holesNode.isEmpty() || holesNode.size() > Round.MAX_HOLES) {
            throw f.error("round.holes", "a round has 1 to " + Round.MAX_HOLES + " holes, got " + holesNode.size());
        }
        List<Round.Hole> holes = new ArrayList<>();
        for (int i = 0; i < holesNode.size(); i++) {
            String p = "round.holes[" + i + "]";
            JsonNode h = f.object(holesNode.get(i), p);
            f.onlyFields(h, p, HOLE);
            String course = f.text(h, p, "course");
            int par = f.integer(h, p, "par", 1, Round.MAX_PAR);
            JsonNode definition = f.object(f.field(h, p, "definition"), p + ".definition");
            World world;
            try {
                // Named by the save itself: its models are looked for beside the save, never where the label "course" points.
                world = worlds.read(JsonFields.MAPPER.writeValueAsString(definition), source);
            } catch (CourseException e) {
                throw new SaveGameException(source, p + ".definition" + (e.path() == null ? "" : "." + e.path()), e.problem(), e);
            } catch (IOException e) {
                throw f.error(p + ".definition", "cannot be read: " + e.getMessage());
            }
            try {
                holes.add(new Round.Hole(course, par, world));
            } catch (IllegalArgumentException e) {
                throw f.error(p, e.getMessage());
            }
        }
        Round round;
        try {
            round = new Round(name, holes, roundSource);
        } catch (IllegalArgumentException e) {
            throw f.error("round", e.getMessage());
        }
        JsonNode holeNode = f.object(f.field(root, null, "hole"), "hole");
        SavedGames.Loaded hole;
        try {
            hole = SavedGames.parse(JsonFields.MAPPER.writeValueAsString(holeNode), source);
        } catch (SaveGameException e) {
            // The current hole is a saved game inside the file: its problems are named by their path under "hole".
            throw new SaveGameException(source, "hole" + (e.path() == null ? "" : "." + e.path()), e.problem(), e);
        } catch (IOException e) {
            throw f.error("hole", "cannot be read: " + e.getMessage());
        }
        JsonNode scoresNode = f.array(root, null, "scores");
        int players = hole.state().players().size();
        if (scoresNode.size() > round.size()) throw f.error("scores", "has " + scoresNode.size() + " holes, the round " + round.size());
        int[][] scores = new int[scoresNode.size()][players];
        for (int i = 0; i < scoresNode.size(); i++) {
            JsonNode row = scoresNode.get(i);
            String p = "scores[" + i + "]";
            if (!row.isArray() || row.size() != players) throw f.error(p, "must hold one score for each of the " + players + " players");
            for (int s = 0; s < players; s++) {
                if (!row.get(s).isIntegralNumber()) throw f.error(p + "[" + s + "]", "must be a whole number");
                scores[i][s] = row.get(s).intValue();
            }
        }
        List<List<ShotRecord>> strokes = new ArrayList<>();
        JsonNode strokesNode = root.get("strokes"); // absent in saves from before it was kept
        if (strokesNode != null) {
            JsonNode arr = f.array(root, null, "strokes");
            if (arr.size() != scores.length) throw f.error("strokes", "has " + arr.size() + " holes, the scores " + scores.length);
            for (int i = 0; i < arr.size(); i++) {
                String p = "strokes[" + i + "]";
                if (!arr.get(i).isArray()) throw f.error(p, "must be an array of strokes");
                strokes.add(SavedGames.readHistory(f, arr.get(i), p, players));
            }
        }
        try {
            return RoundGame.restore(round, scores, strokes, hole.resume());
        } catch (IllegalArgumentException e) {
            throw f.error(null, e.getMessage());
        }
    }
}
