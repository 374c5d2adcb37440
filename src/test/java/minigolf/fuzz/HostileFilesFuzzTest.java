package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import minigolf.cli.MinigolfCommand;
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
 * Mutates every bundled course (every course file under courses/: the examples, bench, holes,
 * chips, friction, hostile, practice and the worlds), a saved game of each and a settings file
 * with a seeded generator ({@link Mutator}) and checks each case ({@link FuzzChecks}): it loads and gives valid JSON of
 * finite numbers, or it is refused with one line that names the file and the problem (exit code 2
 * on the command line). Never a crash, a hang, an internal error or a stack trace. Cases that once
 * failed are kept in src/test/resources/hostile (see {@link HostileRegressionTest}); rounds, saved
 * rounds, models, scores, volumes and online messages are {@link StrangerFilesFuzzTest}'s.
 */
class HostileFilesFuzzTest {
    static final long SEED = 20261124L;
    static final int CASES_PER_COURSE = 20;
    static final int CASES_PER_SAVE = 6;
    static final int SETTINGS_CASES = 300;
    /** As many bundled courses as courses/ holds today (docs/files-from-others.md says "every bundled course"). */
    static final int BUNDLED_COURSES = 125;

    @TempDir
    Path dir;

    private final FuzzChecks checks = new FuzzChecks();

    static Path projectDir() {
        return FuzzChecks.projectDir();
    }

    @Test
    void everyBundledCourseIsFuzzed() throws Exception {
        List<Path> courses = FuzzChecks.bundledCourses();
        Path root = projectDir().resolve("courses");
        java.util.Set<String> folders = new java.util.TreeSet<>();
        for (Path c : courses) folders.add(root.relativize(c).getParent() == null ? "." : root.relativize(c).getParent().toString());
        assertEquals(List.of(".", "bench", "chips", "friction", "holes", "hostile", "practice", "worlds/canyon", "worlds/seaside", "worlds/winter"),
                List.copyOf(folders));
        assertTrue(courses.size() >= BUNDLED_COURSES, "every bundled course: " + courses.size());
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
        Path bundled = projectDir().resolve("courses");
        for (Path course : FuzzChecks.bundledCourses()) {
            String json = Files.readString(course);
            Path folder = courses.resolve(bundled.relativize(course).getParent() == null ? "" : bundled.relativize(course).getParent().toString());
            Files.createDirectories(folder);
            String name = bundled.relativize(course).toString();
            for (int i = 0; i < CASES_PER_COURSE; i++) courseCase(folder, name, course.getFileName().toString(), json, seed++);
            String save = saveOf(course);
            if (save != null) saves.add(save);
        }
        for (String save : saves) {
            for (int i = 0; i < CASES_PER_SAVE; i++) saveCase(save, seed++);
        }
        String settings = settingsJson();
        for (int i = 0; i < SETTINGS_CASES; i++) settingsCase(settings, seed++);
        checks.report("fuzz", 2600);
    }

    /** A course case through the command line: {@code simulate FILE --velocity 1,0.2}. */
    private void courseCase(Path folder, String name, String fileName, String json, long seed) throws IOException {
        checks.started();
        Mutator.Case c = Mutator.mutate(json, seed);
        Path file = folder.resolve("case-" + seed + "-" + fileName);
        Files.write(file, c.bytes());
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code;
        try {
            code = MinigolfCommand.execute(new String[]{"simulate", file.toString(), "--velocity", "1,0.2"},
                    new PrintWriter(out), new PrintWriter(err));
        } catch (RuntimeException | Error e) {
            checks.failure(FuzzChecks.describe(name, seed, c) + ": threw " + e);
            return;
        } finally {
            Files.deleteIfExists(file);
        }
        String what = FuzzChecks.describe(name, seed, c);
        checks.count("course " + c.kind(), code == 0);
        if (code == 0) {
            checks.finiteJson(what, out.toString());
        } else if (code == 2) {
            // A course whose maxSpeed is below the test's 1.02 m/s makes the shot itself the problem (seaside-01, maxSpeed 1e-9).
            String tooFast = "minigolf: --velocity: shot speed ";
            checks.oneLine(what, err.toString(), err.toString().startsWith(tooFast) ? tooFast : "minigolf: " + file + ": ");
        } else {
            checks.failure(what + ": exit " + code + ": " + err);
        }
    }

    /** A saved game of the course after a stroke, with a second stroke rolling; null where no putt stays in play. */
    private static String saveOf(Path course) throws Exception {
        World world = World.load(course);
        Game game = new Game(world, SimulationSettings.DEFAULT.withIntegrator(Integrator.RK2),
                List.of(Player.human("Ann"), Player.bot("Robo", "planner")), 7);
        double v = Math.min(1.0, world.physics().maxSpeed() * 0.5);
        game.play(v, 0.1);
        if (game.isOver()) return SavedGames.toJson(game);
        game.startShot(0.3 * v, -0.1);
        return SavedGames.toJson(game);
    }

    private void saveCase(String json, long seed) throws IOException {
        checks.started();
        Mutator.Case c = Mutator.mutate(json, seed);
        Path file = dir.resolve("save-" + seed + ".json");
        Files.write(file, c.bytes());
        String what = FuzzChecks.describe("saved game", seed, c);
        checks.loadOrRefuse("save " + c.kind(), what, file + ": ", () -> {
            Game game = SavedGames.load(file).resume();
            if (game.activeStroke() != null) {
                for (int i = 0; i < 100_000 && game.activeStroke() != null && !game.activeStroke().isFinished(); i++) {
                    game.activeStroke().step();
                }
                game.completeShot();
            }
            checks.finiteJson(what, SavedGames.toJson(game));
        });
        Files.deleteIfExists(file);
    }

    private static String settingsJson() throws Exception {
        return "{\"integrator\": \"rk4\", \"dt\": 0.016666666666666666, \"vsync\": true, \"frameLimit\": 60,"
                + " \"fullscreen\": false, \"mouseSpeed\": 1.0, \"strokeLimit\": 10, \"heightColours\": false,"
                + " \"playerNames\": [\"Ann\", \"Bob\"]}";
    }

    private void settingsCase(String json, long seed) throws IOException {
        checks.started();
        Mutator.Case c = Mutator.mutate(json, seed);
        Path folder = dir.resolve("settings-" + seed);
        SettingsStore store = new SettingsStore(folder);
        Files.createDirectories(folder);
        Files.write(store.file(), c.bytes());
        String what = FuzzChecks.describe("settings", seed, c);
        try {
            UserSettings s = store.load();
            store.save(s);
            checks.finiteJson(what, Files.readString(store.file()));
            checks.count("settings " + c.kind(), true);
        } catch (SaveGameException e) {
            checks.count("settings " + c.kind(), false);
            checks.oneLine(what, e.getMessage() + "\n", store.file() + ": ");
            try {
                // The game starts with the defaults; saving then keeps the broken file beside.
                String[] problem = new String[1];
                store.save(store.loadOrDefaults(problem));
                if (problem[0] == null) checks.failure(what + ": loadOrDefaults gave no problem");
                if (!Files.exists(folder.resolve("settings.broken.json"))) checks.failure(what + ": the broken file was not kept");
                else if (!java.util.Arrays.equals(c.bytes(), Files.readAllBytes(folder.resolve("settings.broken.json")))) {
                    checks.failure(what + ": the kept broken file changed");
                }
            } catch (SaveGameException again) {
                checks.failure(what + ": saving the defaults failed: " + again.getMessage());
            }
        } catch (RuntimeException | Error e) {
            checks.failure(what + ": threw " + e);
        }
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
