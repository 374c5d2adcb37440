package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.cli.MinigolfCommand;
import minigolf.course.CourseException;
import minigolf.course.Limits;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every finding of issue 16, kept as a case: each is refused in one line (exit code 2), quickly and without leaking. */
class HostileRegressionTest {
    @TempDir
    Path dir;

    private record Run(int code, String out, String err) {
    }

    private static Run simulate(Path course) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = MinigolfCommand.execute(new String[]{"simulate", course.toString(), "--velocity", "1,0"},
                new PrintWriter(out), new PrintWriter(err));
        return new Run(code, out.toString(), err.toString());
    }

    /** Exit 2 and one line "minigolf: FILE: ..." that contains {@code expected}. */
    private static String refused(Path course, String expected) {
        Run r = simulate(course);
        assertEquals(2, r.code, r.err);
        assertEquals("", r.out);
        String line = r.err.strip();
        assertFalse(line.contains("\n"), "one line: " + r.err);
        assertTrue(line.startsWith("minigolf: " + course + ": "), line);
        assertTrue(line.contains(expected), "expected '" + expected + "' in: " + line);
        return line;
    }

    private static String course(String terrain, String zones, String obstacles) {
        return "{\"format\": 1, \"name\": \"hostile\", \"terrain\": " + terrain + ", \"bounds\": {\"min\": [-5, -3], \"max\": [5, 3]},"
                + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2, \"maxSpeed\": 5},"
                + " \"start\": [-4, 0], \"hole\": {\"position\": [4, 0], \"radius\": 0.1},"
                + " \"zones\": " + zones + ", \"obstacles\": " + obstacles + "}";
    }

    private Path write(String name, String text) throws IOException {
        Path f = dir.resolve(name);
        Files.createDirectories(f.getParent());
        Files.writeString(f, text);
        return f;
    }

    private static String model(String file) {
        return "[{\"type\": \"model\", \"file\": \"" + file.replace("\\", "\\\\") + "\", \"position\": [0, 0, 0.1]}]";
    }

    private static Path resource(String name) {
        return HostileFilesFuzzTest.projectDir().resolve("src/test/resources/hostile").resolve(name);
    }

    // ---- model paths: confined to the course's folder and the bundled models ----

    @Test
    void modelPathsOutsideTheFolderAreRefusedWithoutEchoingContent() throws IOException {
        String[][] cases = {
                {"model-absolute.json", "obstacles[0].file: /etc/passwd: refused: an absolute path"},
                {"model-dotdot.json", "obstacles[0].file: ../../../../../../etc/passwd: refused: the path leaves the course's folder"},
                {"model-proc-environ.json", "obstacles[0].file: /proc/self/environ: refused: an absolute path"},
                {"model-inner-dotdot.json", "refused: the path leaves the course's folder"},
                {"model-windows-absolute.json", "refused: an absolute path"},
                {"model-class-resource.json", "refused: the path leaves the course's folder"},
        };
        for (String[] c : cases) {
            Path copy = dir.resolve("courses").resolve(c[0]);
            Files.createDirectories(copy.getParent());
            Files.copy(resource(c[0]), copy);
            String line = refused(copy, c[1]);
            assertFalse(line.contains("root:"), line);
            assertFalse(line.contains("PATH="), line);
        }
    }

    @Test
    void linksOutOfTheFolderAndSpecialFilesAreRefused() throws IOException {
        Path outside = write("outside/secret.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Path folder = dir.resolve("course");
        Files.createDirectories(folder.resolve("models"));
        Files.createSymbolicLink(folder.resolve("models/out.obj"), outside);
        Files.createSymbolicLink(folder.resolve("models/zero.obj"), Path.of("/dev/zero"));
        Files.createSymbolicLink(folder.resolve("models/outdir"), outside.getParent());
        Files.copy(outside, folder.resolve("models/in.obj"));
        Files.createSymbolicLink(folder.resolve("models/alias.obj"), folder.resolve("models/in.obj"));

        refused(write("course/a.json", course("{\"height\": \"0.1\"}", "[]", model("models/out.obj"))),
                "models/out.obj: refused: a link that leads out of the course's folder");
        refused(write("course/b.json", course("{\"height\": \"0.1\"}", "[]", model("models/zero.obj"))),
                "models/zero.obj: refused: a link that leads out of the course's folder");
        refused(write("course/c.json", course("{\"height\": \"0.1\"}", "[]", model("models/outdir/secret.obj"))),
                "refused: a link that leads out of the course's folder");
        refused(write("course/d.json", course("{\"height\": \"0.1\"}", "[]", model("models"))),
                "models: cannot read: is a directory, not a file");
        // A link that stays inside the folder is fine.
        assertEquals(0, simulate(write("course/e.json", course("{\"height\": \"0.1\"}", "[]", model("models/alias.obj")))).code);
        if (mkfifo(folder.resolve("models/fifo.obj"))) {
            refused(write("course/f.json", course("{\"height\": \"0.1\"}", "[]", model("models/fifo.obj"))),
                    "models/fifo.obj: cannot read: not a regular file (a FIFO, device or socket): refused");
        }
    }

    private static boolean mkfifo(Path path) {
        try {
            return new ProcessBuilder("mkfifo", path.toString()).start().waitFor() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    // ---- sizes and counts: checked before the work ----

    @Test
    void theThreeMillionFaceModelIsRefusedByItsSize() throws IOException {
        Path obj = dir.resolve("faces.obj");
        try (Writer w = Files.newBufferedWriter(obj)) {
            w.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
            for (int i = 0; i < 3_000_000; i++) w.write("f 1 2 3\n");
        }
        refused(write("faces.json", course("{\"height\": \"0.1\"}", "[]", model("faces.obj"))),
                "obstacles[0].file: faces.obj: cannot read: too large: 24000024 bytes (the limit is " + Limits.MODEL_FILE_BYTES);
    }

    @Test
    void facesAndVerticesPerModelAreLimited() throws IOException {
        StringBuilder faces = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (int i = 0; i <= Limits.MODEL_TRIANGLES; i++) faces.append("f 1 2 3\n");
        write("faces.obj", faces.toString());
        refused(write("faces.json", course("{\"height\": \"0.1\"}", "[]", model("faces.obj"))),
                "obstacles[0].file: faces.obj: line " + (Limits.MODEL_TRIANGLES + 4) + ": more than "
                        + Limits.MODEL_TRIANGLES + " triangles (the limit)");
        // One polygon with more corners than the limit allows triangles: refused before it is split.
        StringBuilder fan = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\nf");
        for (int i = 0; i < Limits.MODEL_TRIANGLES + 3; i++) fan.append(" ").append(1 + i % 3);
        write("fan.obj", fan.append('\n').toString());
        refused(write("fan.json", course("{\"height\": \"0.1\"}", "[]", model("fan.obj"))), "triangles (the limit)");
        StringBuilder vertices = new StringBuilder();
        for (int i = 0; i <= Limits.MODEL_VERTICES; i++) vertices.append("v 0 0 0\n");
        write("vertices.obj", vertices.append("f 1 2 3\n").toString());
        refused(write("vertices.json", course("{\"height\": \"0.1\"}", "[]", model("vertices.obj"))),
                "more than " + Limits.MODEL_VERTICES + " vertices (the limit)");
    }

    @Test
    void obstaclesZonesPointsGridAndTrianglesInAllAreLimited() throws IOException {
        StringBuilder walls = new StringBuilder("[");
        for (int i = 0; i < 20_000; i++) {
            walls.append(i > 0 ? "," : "").append("{\"type\": \"wall\", \"from\": [-5, -3], \"to\": [5, 3], \"thickness\": 0.05, \"height\": 0.1}");
        }
        refused(write("walls.json", course("{\"height\": \"0.1\"}", "[]", walls.append(']').toString())),
                "obstacles: too many obstacles: 20000 (the limit is " + Limits.OBSTACLES + ")");

        // 300 windmills: 10,560 triangles each.
        StringBuilder mills = new StringBuilder("[");
        for (int i = 0; i < 300; i++) mills.append(i > 0 ? "," : "").append(model("models/windmill.obj"), 1, model("models/windmill.obj").length() - 1);
        int allowed = Limits.TRIANGLES / 10_560;
        refused(write("mills.json", course("{\"height\": \"0.1\"}", "[]", mills.append(']').toString())),
                "obstacles[" + allowed + "]: too many model triangles in all: " + 10_560L * (allowed + 1));

        StringBuilder points = new StringBuilder("[");
        for (int i = 0; i <= Limits.POLYGON_POINTS; i++) {
            double a = 2 * Math.PI * i / (Limits.POLYGON_POINTS + 1);
            points.append(i > 0 ? "," : "").append("[").append(Math.cos(a)).append(", ").append(Math.sin(a)).append("]");
        }
        String zone = "{\"shape\": {\"type\": \"polygon\", \"points\": " + points.append(']') + "}, \"kineticFriction\": 0.3, \"staticFriction\": 0.4}";
        refused(write("polygon.json", course("{\"height\": \"0.1\"}", "[" + zone + "]", "[]")),
                "zones[0].shape.points: too many points: " + (Limits.POLYGON_POINTS + 1) + " (the limit is " + Limits.POLYGON_POINTS + ")");

        StringBuilder circles = new StringBuilder("[");
        for (int i = 0; i <= Limits.ZONES; i++) {
            circles.append(i > 0 ? "," : "").append("{\"shape\": {\"type\": \"circle\", \"center\": [0, 0], \"radius\": 1}, \"kineticFriction\": 0.3, \"staticFriction\": 0.4}");
        }
        refused(write("zones.json", course("{\"height\": \"0.1\"}", circles.append(']').toString(), "[]")),
                "zones: too many zones: " + (Limits.ZONES + 1));

        int n = (int) Math.sqrt(Limits.GRID_NODES) + 1;
        StringBuilder grid = new StringBuilder("{\"grid\": {\"origin\": [-5, -3], \"spacing\": 0.01, \"heights\": [");
        for (int j = 0; j < n; j++) grid.append(j > 0 ? "," : "").append("[").append("0.1,".repeat(n - 1)).append("0.1]");
        refused(write("grid.json", course(grid.append("]}}").toString(), "[]", "[]")),
                "terrain.grid.heights: too many grid nodes: " + n + " rows of " + n);
    }

    @Test
    void filesOverTheSizeLimitAreRefusedBeforeReading() throws IOException {
        Path big = dir.resolve("big.json");
        try (Writer w = Files.newBufferedWriter(big)) {
            w.write(course("{\"height\": \"0.1\"}", "[]", "[]"));
            for (long i = 0; i <= Limits.COURSE_FILE_BYTES / 64; i++) w.write(" ".repeat(64));
        }
        refused(big, "cannot read: too large: ");
    }

    @Test
    void runawayTerrainsAndDeepNestingAreRefused() throws IOException {
        Path exp = dir.resolve("exp4.json");
        Files.copy(resource("exp4.json"), exp);
        refused(exp, "terrain.height: the height at (");
        Path deep = dir.resolve("deep.json");
        Files.copy(resource("deep-nesting.json"), deep);
        refused(deep, "not valid JSON: nested more than " + Limits.JSON_DEPTH + " levels deep (the limit)");
    }

    // ---- what a file is: special files, encodings, blanks ----

    @Test
    void specialFilesEncodingsAndBlankFilesSayWhatIsWrong() throws IOException {
        Path zero = dir.resolve("zero.json");
        Files.createSymbolicLink(zero, Path.of("/dev/zero"));
        refused(zero, "cannot read: not a regular file (a FIFO, device or socket): refused");
        refused(dir, "cannot read: is a directory, not a file");
        Path fifo = dir.resolve("fifo.json");
        if (mkfifo(fifo)) refused(fifo, "cannot read: not a regular file (a FIFO, device or socket): refused");
        String json = course("{\"height\": \"0.1\"}", "[]", "[]");
        Path utf16 = dir.resolve("utf16.json");
        Files.write(utf16, json.getBytes(StandardCharsets.UTF_16));
        refused(utf16, "cannot read: UTF-16 text (it starts with a UTF-16 byte-order mark): save it as UTF-8");
        Files.write(utf16, json.getBytes(StandardCharsets.UTF_16LE));
        refused(utf16, "cannot read: UTF-16 text (zero bytes between the characters): save it as UTF-8");
        Path binary = dir.resolve("binary.json");
        Files.write(binary, new byte[]{'{', 0, 1, 2, (byte) 0xff});
        refused(binary, "cannot read: binary data (a zero byte at byte 1), not a text file");
        Path blank = write("blank.json", " ".repeat(200_000));
        refused(blank, "not valid JSON: the file holds only whitespace (200000 characters), no content");
        refused(write("empty.json", ""), "not valid JSON: the file is empty");
    }

    // ---- saved games: the rules of settings and courses ----

    private static String lakeSave(String bot) throws Exception {
        World lake = World.load(HostileFilesFuzzTest.projectDir().resolve("courses/lake.json"));
        return SavedGames.toJson(new Game(lake, SimulationSettings.DEFAULT, List.of(Player.human("Ann"), Player.bot("Robo", bot)), 7));
    }

    private String refusedSave(String json, String expected) throws IOException {
        Path f = write("save.json", json);
        SaveGameException e = assertThrows(SaveGameException.class, () -> SavedGames.load(f));
        assertTrue(e.getMessage().startsWith(f + ": "), e.getMessage());
        assertTrue(e.getMessage().contains(expected), "expected '" + expected + "' in " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void savesAreCheckedAsSettingsAndCoursesAre() throws Exception {
        String save = lakeSave("planner");
        assertNotNull(SavedGames.parse(save, "ok.json"));
        for (String dt : new String[]{"4.9E-324", "1.0E-9", "0.5", "0"}) {
            ObjectNode root = (ObjectNode) Mutator.MAPPER.readTree(save);
            ((ObjectNode) root.get("simulation")).put("dt", Double.parseDouble(dt));
            refusedSave(root.toString(), "simulation.dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got " + Double.parseDouble(dt));
        }
        ObjectNode root = (ObjectNode) Mutator.MAPPER.readTree(save);
        ((ObjectNode) root.get("simulation")).put("maxTime", 1e9);
        refusedSave(root.toString(), "simulation.maxTime: must be 1 to 600.0 s");
        root = (ObjectNode) Mutator.MAPPER.readTree(save);
        ((com.fasterxml.jackson.databind.node.ArrayNode) root.get("players").get(0).get("ball")).removeAll().add(0.0).add(0.0);
        refusedSave(root.toString(), "players[0].ball: lies in water (h = -0.04");
        refusedSave(lakeSave("planner").replace("\"planner\"", "\"no-such-bot\""), "players[1].bot: no bot named \"no-such-bot\" (known: ");
    }

    // ---- settings: special files refused at once, a broken file kept ----

    @Test
    void settingsThatAreSpecialFilesAreRefusedAtOnceAndBrokenOnesKept() throws Exception {
        SettingsStore store = new SettingsStore(dir.resolve("cfg"));
        Files.createDirectories(store.directory());
        Files.createSymbolicLink(store.file(), Path.of("/dev/zero"));
        String[] problem = new String[1];
        assertEquals(UserSettings.DEFAULTS, store.loadOrDefaults(problem));
        assertEquals(store.file() + ": cannot read: not a regular file (a FIFO, device or socket): refused", problem[0]);
        Files.delete(store.file());
        if (mkfifo(store.file())) {
            assertEquals(UserSettings.DEFAULTS, store.loadOrDefaults(problem));
            assertEquals(store.file() + ": cannot read: not a regular file (a FIFO, device or socket): refused", problem[0]);
            Files.delete(store.file());
        }
        Files.write(store.file(), "{\"dt\": 1}".getBytes(StandardCharsets.UTF_16));
        assertEquals(UserSettings.DEFAULTS, store.loadOrDefaults(problem));
        assertEquals(store.file() + ": cannot read: UTF-16 text (it starts with a UTF-16 byte-order mark): save it as UTF-8", problem[0]);
        byte[] broken = Files.readAllBytes(store.file());
        // Saving (the player changed a setting) moves the broken file aside, byte for byte, never over it.
        store.save(UserSettings.DEFAULTS.withFrameLimit(30));
        assertEquals(30, store.load().frameLimit());
        assertTrue(java.util.Arrays.equals(broken, Files.readAllBytes(store.directory().resolve("settings.broken.json"))));
        Files.writeString(store.file(), "{\"dt\": 5}");
        store.save(UserSettings.DEFAULTS);
        assertEquals("{\"dt\": 5}", Files.readString(store.directory().resolve("settings.broken-2.json")));
        assertEquals(UserSettings.DEFAULTS, store.load());
    }
}
