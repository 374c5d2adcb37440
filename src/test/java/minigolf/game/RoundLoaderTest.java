package minigolf.game;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.course.CourseException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Round files: what loads, and the one-line error for each kind of mistake. */
class RoundLoaderTest {
    @TempDir
    Path dir;

    private static final String FLAT = "{\"format\": 1, \"name\": \"Flat %s\", \"terrain\": {\"height\": \"0.1\"},"
            + " \"bounds\": {\"min\": [-5, -5], \"max\": [5, 5]},"
            + " \"physics\": {\"kineticFriction\": 0.1, \"staticFriction\": 0.2},"
            + " \"start\": [-3, 0], \"hole\": {\"position\": [3, 0], \"radius\": 0.1, \"rule\": \"capture\"}}";

    private Path round(String json) throws Exception {
        Files.createDirectories(dir.resolve("holes"));
        Files.writeString(dir.resolve("holes/a.json"), String.format(FLAT, "A"));
        Files.writeString(dir.resolve("holes/b.json"), String.format(FLAT, "B"));
        Path rounds = Files.createDirectories(dir.resolve("rounds"));
        Path file = rounds.resolve("r.json");
        Files.writeString(file, json);
        return file;
    }

    private String error(String json) throws Exception {
        Path file = round(json);
        CourseException e = assertThrows(CourseException.class, () -> RoundLoader.load(file));
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().startsWith(file.toString() + ": "), e.getMessage());
        return e.getMessage().substring(file.toString().length() + 2);
    }

    @Test
    void loadsHolesInOrderRelativeToTheRoundFile() throws Exception {
        Round r = RoundLoader.load(round("{\"format\": 1, \"name\": \"Two\", \"holes\": ["
                + "{\"course\": \"../holes/b.json\", \"par\": 3}, {\"course\": \"../holes/a.json\", \"par\": 2}]}"));
        assertEquals("Two", r.name());
        assertEquals(2, r.size());
        assertEquals("Flat B", r.hole(0).world().course().name());
        assertEquals("Flat A", r.hole(1).world().course().name());
        assertEquals(3, r.hole(0).par());
        assertEquals(5, r.par());
        assertEquals("../holes/b.json", r.hole(0).course());
    }

    @Test
    void errorsNameTheFieldAndTheProblem() throws Exception {
        assertEquals("not valid JSON: the file is empty", error(""));
        assertTrue(error("{\"format\": 1,}").startsWith("not valid JSON at line 1, column 14"));
        assertEquals("expected a JSON object at the top level", error("[1]"));
        assertEquals("format: unsupported format 2 (this game reads round format 1)",
                error("{\"format\": 2, \"name\": \"x\", \"holes\": []}"));
        assertEquals("name: missing required field", error("{\"format\": 1, \"holes\": []}"));
        assertEquals("name: must be a non-empty string", error("{\"format\": 1, \"name\": \" \", \"holes\": []}"));
        assertEquals("holes: a round has 1 to 36 holes, got 0", error("{\"format\": 1, \"name\": \"x\", \"holes\": []}"));
        assertEquals("holes: expected an array of holes", error("{\"format\": 1, \"name\": \"x\", \"holes\": {}}"));
        assertEquals("colour: unknown field (known: format, name, holes)",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [], \"colour\": 1}"));
        assertEquals("holes[0].par: missing required field",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/a.json\"}]}"));
        assertEquals("holes[0].par: must be a whole number from 1 to 9, got 0",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/a.json\", \"par\": 0}]}"));
        assertEquals("holes[0].par: must be a whole number from 1 to 9, got 2.5",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/a.json\", \"par\": 2.5}]}"));
        assertEquals("holes[0].course: must be a non-empty string (a course file)",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": 7, \"par\": 2}]}"));
        assertEquals("holes[0].size: unknown field (known: course, par)",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"a\", \"par\": 2, \"size\": 1}]}"));
    }

    @Test
    void aBrokenCourseNamesTheHoleAndTheCoursesOwnError() throws Exception {
        String msg = error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/a.json\", \"par\": 2},"
                + " {\"course\": \"../holes/missing.json\", \"par\": 2}]}");
        assertEquals("holes[1].course: " + dir.resolve("holes/missing.json") + ": cannot read: no such file", msg);
        Files.writeString(dir.resolve("holes/wet.json"), String.format(FLAT, "W").replace("\"0.1\"", "\"x/10\""));
        msg = error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/wet.json\", \"par\": 2}]}");
        assertEquals("holes[0].course: " + dir.resolve("holes/wet.json") + ": start: (-3, 0) is in water (h = -0.3)", msg);
    }

    /**
     * A round from someone else opens course files only in its folder and the folders beside it (the
     * bundled rounds' ../holes/), never a system file or anything above its collection; what it names
     * outside is refused before it is opened, so nothing of such a file is shown.
     */
    @Test
    void aRoundOnlyReachesItsFolderAndTheFoldersBesideIt() throws Exception {
        Files.createDirectories(dir.resolve("mine"));
        Files.writeString(dir.resolve("mine/c.json"), String.format(FLAT, "C"));
        Files.createDirectories(dir.resolve("rounds"));
        Files.writeString(dir.resolve("rounds/d.json"), String.format(FLAT, "D"));
        Round r = RoundLoader.load(round("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../mine/c.json\", \"par\": 2},"
                + " {\"course\": \"d.json\", \"par\": 2}, {\"course\": \"../rounds/../holes/a.json\", \"par\": 2}]}"));
        assertEquals(List.of("Flat C", "Flat D", "Flat A"), r.holes().stream().map(h -> h.world().course().name()).toList());
        String rule = " (a round names its courses relative to its own file, e.g. ../holes/01-first-tee.json)";
        for (String[] c : new String[][]{
                {"/etc/passwd", "refused: an absolute path" + rule},
                {"../../../../../../../../etc/passwd", "refused: the path leaves the round's folder and the folders beside it" + rule},
                {"../..", "refused: the path leaves the round's folder and the folders beside it" + rule},
                {"..", "refused: the path leaves the round's folder and the folders beside it" + rule},
                {"C:\\\\Windows\\\\win.ini", "refused: an absolute path" + rule},
                {"..\\\\..\\\\..\\\\etc\\\\passwd", "refused: the path leaves the round's folder and the folders beside it" + rule}}) {
            String msg = error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"" + c[0] + "\", \"par\": 2}]}");
            assertEquals("holes[0].course: " + c[0].replace("\\\\", "\\") + ": " + c[1], msg);
        }
        // A link in the collection that leads out of it is refused too, and nothing of its target is quoted.
        Path outside = Files.createTempFile("round-outside", ".json");
        try {
            Files.writeString(outside, "root:x:0:0:root:/root:/bin/bash");
            Files.createSymbolicLink(dir.resolve("holes/link.json"), outside);
            String msg = error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/link.json\", \"par\": 2}]}");
            assertEquals("holes[0].course: ../holes/link.json: refused: a link that leads out of the round's folder and the folders beside it", msg);
            assertFalse(msg.contains("root"), msg);
        } finally {
            Files.deleteIfExists(outside);
        }
        // Within the collection a file that is not a course is reported without its content.
        Files.writeString(dir.resolve("holes/passwd"), "root:x:0:0:root:/root:/bin/bash\n");
        String msg = error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"../holes/passwd\", \"par\": 2}]}");
        assertFalse(msg.contains("root"), msg);
        // The bundled rounds on the classpath: the same rule.
        assertEquals("/courses/holes/01-first-tee.json", RoundLoader.resourceCourse("/courses/rounds/", "../holes/01-first-tee.json"));
        for (String escape : new String[]{"../../minigolf/cli/Main.class", "/minigolf/cli/Main.class", "..", "../../x.json"}) {
            CourseException e = assertThrows(CourseException.class, () -> RoundLoader.resourceCourse("/courses/rounds/", escape));
            assertEquals(escape + ": refused: the path leaves the round's folder and the folders beside it", e.getMessage());
        }
    }

    @Test
    void namesAndFileNamesLongerThanTheLimitsAreRefused() throws Exception {
        assertEquals("name: too long: 100000 characters (the limit is 128)",
                error("{\"format\": 1, \"name\": \"" + "n".repeat(100_000) + "\", \"holes\": []}"));
        String file = "../holes/" + "a/".repeat(600) + "a.json";
        assertEquals("holes[0].course: too long: " + file.length() + " characters (the limit is 1024)",
                error("{\"format\": 1, \"name\": \"x\", \"holes\": [{\"course\": \"" + file + "\", \"par\": 2}]}"));
        Round r = RoundLoader.load(round("{\"format\": 1, \"name\": \"" + "n".repeat(128) + "\", \"holes\": ["
                + "{\"course\": \"../holes/a.json\", \"par\": 2}]}"));
        assertEquals(128, r.name().length());
    }

    @Test
    void theBundledRoundsLoadFromTheClasspathToo() throws Exception {
        Round r = RoundLoader.loadResource("/courses/rounds/meadowbrook-9.json");
        assertEquals(9, r.size());
        assertEquals("First Tee", r.hole(0).world().course().name());
        CourseException e = assertThrows(CourseException.class, () -> RoundLoader.loadResource("/courses/rounds/none.json"));
        assertEquals("/courses/rounds/none.json: cannot read: no such resource", e.getMessage());
    }
}
