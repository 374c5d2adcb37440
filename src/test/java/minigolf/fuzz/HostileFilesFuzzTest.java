package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.stream.Stream;
import minigolf.cli.MinigolfCommand;
import minigolf.course.CourseException;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.Integrator;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Mutates every bundled course, a saved game of each and a settings file with a seeded generator
 * ({@link Mutator}) and checks each case: it loads and gives valid JSON of finite numbers, or it is
 * refused with one line that names the file and the problem (exit code 2 on the command line).
 * Never a crash, a hang, an internal error or a stack trace. Cases that once failed are kept in
 * src/test/resources/hostile (see {@link HostileRegressionTest}).
 */
class HostileFilesFuzzTest {
    static final long SEED = 20261124L;
    static final int CASES_PER_COURSE = 80;
    static final int CASES_PER_SAVE = 12;
    static final int SETTINGS_CASES = 300;

    @TempDir
    Path dir;

    private final List<String> failures = new ArrayList<>();
    private final java.util.Map<String, int[]> outcomes = new java.util.TreeMap<>();
    private int cases;

    private void count(String kind, boolean accepted) {
        outcomes.computeIfAbsent(kind, k -> new int[2])[accepted ? 0 : 1]++;
    }

    static Path projectDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."));
    }

    static List<Path> bundledCourses() throws IOException {
        List<Path> out = new ArrayList<>();
        for (Path folder : List.of(projectDir().resolve("courses"), projectDir().resolve("courses/bench"))) {
            try (Stream<Path> s = Files.list(folder)) {
                s.filter(p -> p.toString().endsWith(".json")).sorted().forEach(out::add);
            }
        }
        return out;
    }

    @Test
    void mutatedFilesLoadOrAreRefusedInOneLine() throws Exception {
        // The mutated courses lie where the originals do relative to their models.
        Path courses = dir.resolve("courses");
        Files.createDirectories(courses.resolve("models"));
        try (Stream<Path> models = Files.list(projectDir().resolve("courses/models"))) {
            for (Path m : (Iterable<Path>) models::iterator) Files.copy(m, courses.resolve("models").resolve(m.getFileName()));
        }
        long seed = SEED;
        List<String> saves = new ArrayList<>();
        for (Path course : bundledCourses()) {
            String json = Files.readString(course);
            for (int i = 0; i < CASES_PER_COURSE; i++) courseCase(courses, course.getFileName().toString(), json, seed++);
            saves.add(saveOf(course));
        }
        for (String save : saves) {
            for (int i = 0; i < CASES_PER_SAVE; i++) saveCase(save, seed++);
        }
        String settings = settingsJson();
        for (int i = 0; i < SETTINGS_CASES; i++) settingsCase(settings, seed++);
        StringBuilder summary = new StringBuilder("fuzz: " + cases + " cases (accepted/refused):");
        outcomes.forEach((k, v) -> summary.append(' ').append(k).append(' ').append(v[0]).append('/').append(v[1]));
        System.out.println(summary);
        assertTrue(cases >= 3000, "at least 3,000 cases, ran " + cases);
        if (!failures.isEmpty()) {
            fail(failures.size() + " of " + cases + " cases failed; the first ones:\n"
                    + String.join("\n", failures.subList(0, Math.min(20, failures.size()))));
        }
    }

    /** A course case through the command line: {@code simulate FILE --velocity 1,0.2}. */
    private void courseCase(Path folder, String name, String json, long seed) throws IOException {
        cases++;
        Mutator.Case c = Mutator.mutate(json, seed);
        Path file = folder.resolve("case-" + seed + "-" + name);
        Files.write(file, c.bytes());
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code;
        try {
            code = MinigolfCommand.execute(new String[]{"simulate", file.toString(), "--velocity", "1,0.2"},
                    new PrintWriter(out), new PrintWriter(err));
        } catch (RuntimeException | Error e) {
            failures.add(describe(name, seed, c) + ": threw " + e);
            return;
        } finally {
            Files.deleteIfExists(file);
        }
        String what = describe(name, seed, c);
        count("course " + c.kind(), code == 0);
        if (code == 0) {
            checkFiniteJson(what, out.toString());
        } else if (code == 2) {
            checkOneLine(what, err.toString(), "minigolf: " + file + ": ");
        } else {
            failures.add(what + ": exit " + code + ": " + err);
        }
        if (c.kind().equals("hostile-path") && (out.toString().contains("root:") || err.toString().contains("root:"))) {
            failures.add(what + ": a system file's content was echoed");
        }
    }

    private String saveOf(Path course) throws Exception {
        World world = World.load(course);
        Game game = new Game(world, SimulationSettings.DEFAULT.withIntegrator(Integrator.RK2),
                List.of(Player.human("Ann"), Player.bot("Robo", "planner")), 7);
        double v = Math.min(1.0, world.physics().maxSpeed() * 0.5);
        game.play(v, 0.1);
        game.startShot(0.3 * v, -0.1);
        return SavedGames.toJson(game);
    }

    private void saveCase(String json, long seed) throws IOException {
        cases++;
        Mutator.Case c = Mutator.mutate(json, seed);
        Path file = dir.resolve("save-" + seed + ".json");
        Files.write(file, c.bytes());
        String what = describe("saved game", seed, c);
        try {
            SavedGames.Loaded loaded = SavedGames.load(file);
            Game game = loaded.resume();
            if (game.activeStroke() != null) {
                for (int i = 0; i < 100_000 && game.activeStroke() != null && !game.activeStroke().isFinished(); i++) {
                    game.activeStroke().step();
                }
                game.completeShot();
            }
            checkFiniteJson(what, SavedGames.toJson(game));
            count("save " + c.kind(), true);
        } catch (CourseException e) {
            count("save " + c.kind(), false);
            checkOneLine(what, e.getMessage() + "\n", file + ": ");
        } catch (RuntimeException | Error e) {
            failures.add(what + ": threw " + e);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    private static String settingsJson() throws Exception {
        return "{\"integrator\": \"rk4\", \"dt\": 0.016666666666666666, \"vsync\": true, \"frameLimit\": 60,"
                + " \"fullscreen\": false, \"mouseSpeed\": 1.0, \"strokeLimit\": 10, \"heightColours\": false,"
                + " \"playerNames\": [\"Ann\", \"Bob\"]}";
    }

    private void settingsCase(String json, long seed) throws IOException {
        cases++;
        Mutator.Case c = Mutator.mutate(json, seed);
        Path folder = dir.resolve("settings-" + seed);
        SettingsStore store = new SettingsStore(folder);
        Files.createDirectories(folder);
        Files.write(store.file(), c.bytes());
        String what = describe("settings", seed, c);
        try {
            UserSettings s = store.load();
            store.save(s);
            checkFiniteJson(what, Files.readString(store.file()));
            count("settings " + c.kind(), true);
        } catch (SaveGameException e) {
            count("settings " + c.kind(), false);
            checkOneLine(what, e.getMessage() + "\n", store.file() + ": ");
            try {
                // The game starts with the defaults; saving then keeps the broken file beside.
                String[] problem = new String[1];
                store.save(store.loadOrDefaults(problem));
                if (problem[0] == null) failures.add(what + ": loadOrDefaults gave no problem");
                if (!Files.exists(folder.resolve("settings.broken.json"))) failures.add(what + ": the broken file was not kept");
                else if (!java.util.Arrays.equals(c.bytes(), Files.readAllBytes(folder.resolve("settings.broken.json")))) {
                    failures.add(what + ": the kept broken file changed");
                }
            } catch (SaveGameException again) {
                failures.add(what + ": saving the defaults failed: " + again.getMessage());
            }
        } catch (RuntimeException | Error e) {
            failures.add(what + ": threw " + e);
        }
    }

    private static String describe(String name, long seed, Mutator.Case c) {
        return name + " seed " + seed + " (" + c.kind() + ": " + shorten(c.detail()) + ")";
    }

    private static String shorten(String s) {
        return s.length() > 120 ? s.substring(0, 117) + "..." : s;
    }

    private void checkOneLine(String what, String err, String prefix) {
        String e = err.endsWith("\n") ? err.substring(0, err.length() - 1) : err;
        if (e.isEmpty() || e.contains("\n")) {
            failures.add(what + ": not one line: " + shorten(err));
        } else if (!e.startsWith(prefix)) {
            failures.add(what + ": does not start with " + prefix + ": " + shorten(e));
        } else if (e.contains("internal error") || e.contains("Exception") || e.contains("\tat ")) {
            failures.add(what + ": an internal error: " + shorten(e));
        } else if (e.length() - prefix.length() < 8) {
            failures.add(what + ": says nothing: " + e);
        }
    }

    private void checkFiniteJson(String what, String json) {
        try {
            JsonNode root = Mutator.MAPPER.readTree(json);
            if (root == null || !root.isObject()) {
                failures.add(what + ": output is not a JSON object: " + shorten(json));
                return;
            }
            String bad = nonFinite(root, "");
            if (bad != null) failures.add(what + ": a non-finite number at " + bad);
        } catch (IOException e) {
            failures.add(what + ": output is not valid JSON: " + shorten(json));
        }
    }

    private static String nonFinite(JsonNode n, String path) {
        if (n.isNumber()) return Double.isFinite(n.doubleValue()) ? null : path;
        if (n.isTextual()) {
            String t = n.textValue();
            return t.equals("NaN") || t.endsWith("Infinity") ? path : null;
        }
        if (n.isObject()) {
            for (Iterator<String> it = n.fieldNames(); it.hasNext(); ) {
                String f = it.next();
                String bad = nonFinite(n.get(f), path + "." + f);
                if (bad != null) return bad;
            }
        }
        if (n.isArray()) {
            for (int i = 0; i < n.size(); i++) {
                String bad = nonFinite(n.get(i), path + "[" + i + "]");
                if (bad != null) return bad;
            }
        }
        return null;
    }

    @Test
    void theGeneratorIsDeterministic() throws Exception {
        String json = Files.readString(projectDir().resolve("courses/lake.json"));
        for (long s = 0; s < 50; s++) {
            assertEquals(new String(Mutator.mutate(json, s).bytes(), StandardCharsets.ISO_8859_1),
                    new String(Mutator.mutate(json, s).bytes(), StandardCharsets.ISO_8859_1));
        }
    }
}
