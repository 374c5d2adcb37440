package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.HighScores;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.RoundLoader;
import minigolf.game.SavedRounds;
import minigolf.online.ClientMessages;
import minigolf.online.ProtocolException;
import minigolf.online.RoomEvent;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Everything else a stranger can send, fuzzed with the seeded generators ({@link Mutator} for JSON,
 * {@link ObjMutator} for models): round files (in a copy of the bundled collection, so a hole's
 * course may be a hostile path), saved rounds, .obj models (through a course that places them),
 * the high-score table, the volumes file, and the online protocol's messages a server reads
 * (every kind of client message) and a client reads (room events). Each case loads to finite
 * JSON or is refused in one line naming its file ({@link FuzzChecks}); a protocol message is refused
 * with a {@link ProtocolException} of a known code. Classic track files, their index and sprite
 * sheets: {@link ClassicTracksFuzzTest}.
 */
class StrangerFilesFuzzTest {
    static final long SEED = 20261127L;
    static final int ROUND_CASES = 200, SAVED_ROUND_CASES = 200, MODEL_CASES = 300, SCORES_CASES = 150,
            VOLUMES_CASES = 100, MESSAGE_CASES = 40, EVENT_CASES = 150;
    /** The protocol's error codes for a message it refuses (docs/online.md, "Errors"). */
    private static final List<String> CODES = List.of("bad-message", "bad-field", "too-large", "version");

    @TempDir
    Path dir;

    private final FuzzChecks checks = new FuzzChecks();

    @Test
    void everyOtherFileAndMessageLoadsOrIsRefusedInOneLine() throws Exception {
        long seed = SEED;
        seed = rounds(seed);
        seed = savedRounds(seed);
        seed = models(seed);
        seed = scoresAndVolumes(seed);
        messages(seed);
        checks.report("fuzz, the other files and messages", ROUND_CASES + SAVED_ROUND_CASES + MODEL_CASES);
    }

    /** Round files, mutated, in a copy of courses/ (rounds/ beside holes/, as the game installs them). */
    private long rounds(long seed) throws Exception {
        Path courses = dir.resolve("courses");
        for (String folder : List.of("rounds", "holes", "models")) {
            Files.createDirectories(courses.resolve(folder));
            try (Stream<Path> files = Files.list(FuzzChecks.projectDir().resolve("courses").resolve(folder))) {
                for (Path f : (Iterable<Path>) files::iterator) Files.copy(f, courses.resolve(folder).resolve(f.getFileName()));
            }
        }
        // A short round of three holes (the windmill's model included) keeps each case cheap; the bundled ones too.
        String three = "{\"format\": 1, \"name\": \"Three\", \"holes\": [{\"course\": \"../holes/01-first-tee.json\", \"par\": 2},"
                + " {\"course\": \"../holes/03-windmill.json\", \"par\": 2}, {\"course\": \"../holes/05-island.json\", \"par\": 3}]}";
        List<String> rounds = List.of(three, three, three, Files.readString(courses.resolve("rounds/meadowbrook-9.json")));
        for (int i = 0; i < ROUND_CASES; i++, seed++) {
            checks.started();
            Mutator.Case c = Mutator.mutate(rounds.get(i % rounds.size()), seed);
            Path file = courses.resolve("rounds/case-" + seed + ".json");
            Files.write(file, c.bytes());
            String what = FuzzChecks.describe("round", seed, c);
            checks.loadOrRefuse("round " + c.kind(), what, file + ": ", () -> {
                RoundGame rg = new RoundGame(RoundLoader.load(file), SimulationSettings.DEFAULT, List.of(Player.human("Ann")), 10);
                checks.finiteJson(what, SavedRounds.toJson(rg));
            });
            Files.deleteIfExists(file);
        }
        return seed;
    }

    /** A saved round after one hole, the second's stroke rolling, mutated; a loaded one is played on and saved again. */
    private long savedRounds(long seed) throws Exception {
        Round full = RoundLoader.load(FuzzChecks.projectDir().resolve("courses/rounds/meadowbrook-9.json"));
        Round three = new Round("Three", List.of(full.hole(0), full.hole(2), full.hole(4)), "three");
        RoundGame rg = new RoundGame(three, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.bot("Robo", "planner")), 10);
        rg.game().play(1.5, 0.2);
        rg.game().play(1.0, -0.1);
        rg.game().startShot(0.5, 0);
        String json = SavedRounds.toJson(rg);
        for (int i = 0; i < SAVED_ROUND_CASES; i++, seed++) {
            checks.started();
            Mutator.Case c = Mutator.mutate(json, seed);
            Path file = dir.resolve("round-save-" + seed + ".json");
            Files.write(file, c.bytes());
            String what = FuzzChecks.describe("saved round", seed, c);
            checks.loadOrRefuse("saved round " + c.kind(), what, file + ": ", () -> {
                RoundGame back = SavedRounds.load(file);
                Game g = back.game();
                if (g.activeStroke() != null) {
                    for (int k = 0; k < 100_000 && !g.activeStroke().isFinished(); k++) g.activeStroke().step();
                    g.completeShot();
                }
                checks.finiteJson(what, SavedRounds.toJson(back));
            });
            Files.deleteIfExists(file);
        }
        return seed;
    }

    /** Models, mutated as text, placed by a course beside them: the course loads or names the model's problem in one line. */
    private long models(long seed) throws Exception {
        Path folder = Files.createDirectories(dir.resolve("models-case"));
        String windmill = Files.readString(FuzzChecks.projectDir().resolve("courses/models/windmill.obj"));
        String mtl = Files.readString(FuzzChecks.projectDir().resolve("courses/models/windmill.mtl"));
        Files.writeString(folder.resolve("windmill.mtl"), mtl);
        String tetra = "mtllib windmill.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nusemtl roof\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
        String course = "{\"format\": 1, \"name\": \"model\", \"terrain\": {\"height\": \"0.1\"},"
                + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]}, \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
                + " \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1},"
                + " \"obstacles\": [{\"type\": \"model\", \"file\": \"case.obj\", \"position\": [0, 2, 0.1], \"scale\": 0.5}]}";
        Path courseFile = folder.resolve("model-course.json");
        Files.writeString(courseFile, course);
        for (int i = 0; i < MODEL_CASES; i++, seed++) {
            checks.started();
            ObjMutator.Case c = ObjMutator.mutate(i % 3 == 0 ? windmill : tetra, seed);
            Files.write(folder.resolve("case.obj"), c.bytes());
            String what = "model seed " + seed + " (" + c.kind() + ": " + FuzzChecks.shorten(c.detail()) + ")";
            checks.loadOrRefuse("model " + c.kind(), what, courseFile + ": obstacles[0].file: ", () -> {
                if (World.load(courseFile).obstacles() == null) checks.failure(what + ": the model's obstacle is gone");
            });
        }
        return seed;
    }

    /** The high-score table and the volumes file: they load and save to finite JSON, or are refused in one line. */
    private long scoresAndVolumes(long seed) throws Exception {
        Path config = Files.createDirectories(dir.resolve("config"));
        Path scoresFile = HighScores.file(config);
        HighScores scores = new HighScores();
        scores.recordHole("Meadowbrook Front Nine", 0, List.of(Player.human("Ann"), Player.human("Bob")), new int[]{2, 3});
        scores.save(scoresFile);
        String scoresJson = Files.readString(scoresFile);
        Path volumesFile = AudioSettings.file(config);
        AudioSettings.DEFAULTS.save(volumesFile);
        String volumesJson = Files.readString(volumesFile);
        for (int i = 0; i < SCORES_CASES + VOLUMES_CASES; i++, seed++) {
            checks.started();
            boolean isScores = i < SCORES_CASES;
            Path file = isScores ? scoresFile : volumesFile;
            Mutator.Case c = Mutator.mutate(isScores ? scoresJson : volumesJson, seed);
            Files.write(file, c.bytes());
            String kind = (isScores ? "scores " : "volumes ") + c.kind(), what = FuzzChecks.describe(kind, seed, c);
            checks.loadOrRefuse(kind, what, file + ": ", () -> {
                Path again = dir.resolve("again.json");
                if (isScores) HighScores.load(file).save(again);
                else AudioSettings.load(file).save(again);
                checks.finiteJson(what, Files.readString(again));
            });
        }
        return seed;
    }

    /** Online: every kind of client message as the server reads it, and room events as clients and the store read them. */
    private void messages(long seed) throws Exception {
        List<String> messages = List.of(
                "{\"type\": \"create\", \"protocol\": 1, \"name\": \"Ann\", \"course\": \"meadowbrook-9\", \"seats\": 3,"
                        + " \"bots\": [\"planner\"], \"listed\": true, \"strokeLimit\": 10}",
                "{\"type\": \"join\", \"protocol\": 1, \"room\": \"ABCDE\", \"name\": \"Bob\"}",
                "{\"type\": \"resume\", \"protocol\": 1, \"room\": \"ABCDE\", \"token\": \"abcdefghijklmnopqrstuv\"}",
                "{\"type\": \"shot\", \"seq\": 3, \"velocity\": [1.5, -0.2], \"loft\": 10, \"wait\": 2.5}",
                "{\"type\": \"chat\", \"text\": \"nice putt\"}", "{\"type\": \"leave\"}", "{\"type\": \"ping\"}",
                "{\"type\": \"sync\"}");
        for (String message : messages) {
            for (int i = 0; i < MESSAGE_CASES; i++, seed++) {
                checks.started();
                Mutator.Case c = Mutator.mutate(message, seed);
                String text = new String(c.bytes(), StandardCharsets.UTF_8), what = FuzzChecks.describe("client message", seed, c);
                try {
                    ClientMessages.parse(text);
                    checks.count("message " + c.kind(), true);
                } catch (ProtocolException e) {
                    checks.count("message " + c.kind(), false);
                    protocolRefusal(what, e);
                } catch (RuntimeException | Error e) {
                    checks.failure(what + ": threw " + e);
                }
            }
        }
        String event = "{\"type\": \"stroke\", \"seq\": 4, \"hole\": 1, \"seat\": 1, \"start\": [-3, 0], \"velocity\": [1.5, 0.2, 0],"
                + " \"outcome\": \"stopped\", \"end\": [-1.2, 0.3], \"ball\": [-1.2, 0.3], \"strokes\": 2, \"penalties\": 0,"
                + " \"status\": \"playing\", \"wait\": 0, \"turn\": 0}";
        for (int i = 0; i < EVENT_CASES; i++, seed++) {
            checks.started();
            Mutator.Case c = Mutator.mutate(event, seed);
            String what = FuzzChecks.describe("room event", seed, c);
            JsonNode node;
            try {
                node = minigolf.online.Json.parse(new String(c.bytes(), StandardCharsets.UTF_8));
            } catch (ProtocolException e) {
                checks.count("event " + c.kind(), false);
                protocolRefusal(what, e);
                continue;
            } catch (RuntimeException | Error e) {
                checks.failure(what + ": threw " + e);
                continue;
            }
            try {
                RoomEvent.parse(node, 4);
                checks.count("event " + c.kind(), true);
            } catch (ProtocolException e) {
                checks.count("event " + c.kind(), false);
                protocolRefusal(what, e);
            } catch (RuntimeException | Error e) {
                checks.failure(what + ": threw " + e);
            }
        }
    }

    private void protocolRefusal(String what, ProtocolException e) {
        if (!CODES.contains(e.code())) checks.failure(what + ": error code " + e.code());
        String m = String.valueOf(e.getMessage());
        if (m.isBlank() || m.contains("\n") || m.contains("Exception")) checks.failure(what + ": message " + FuzzChecks.shorten(m));
    }

    @Test
    void theModelGeneratorIsDeterministic() throws Exception {
        String obj = Files.readString(FuzzChecks.projectDir().resolve("courses/models/windmill.obj"));
        for (long s = 0; s < 30; s++) {
            assertEquals(new String(ObjMutator.mutate(obj, s).bytes(), StandardCharsets.ISO_8859_1),
                    new String(ObjMutator.mutate(obj, s).bytes(), StandardCharsets.ISO_8859_1));
        }
    }
}
