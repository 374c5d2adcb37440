package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Every command with broken inputs (missing files, folders, binary files, special files, bad
 * numbers, no display): exit code 2 and one line on stderr, never an internal error.
 */
class BrokenInputsTest {
    @TempDir
    Path dir;

    private static final String[] COURSE_COMMANDS = {"play", "simulate", "bench-physics", "bench-accuracy", "render",
            "bench-render", "solve", "edit"};

    /** The options a command needs besides its course to get as far as reading it. */
    private String[] args(String command, String course) {
        return switch (command) {
            case "simulate" -> new String[]{command, course, "--velocity", "1,0"};
            case "render" -> new String[]{command, course, "--out", dir.resolve("x.png").toString()};
            case "play", "edit" -> new String[]{command, course, "--frames", "1"};
            default -> new String[]{command, course};
        };
    }

    private static void assertOneLineExit2(CliRun r, String what, String expected) {
        assertEquals(2, r.code(), what + ": " + r.err());
        String err = r.err().strip();
        assertFalse(err.isEmpty() || err.contains("\n"), what + ": one line: " + r.err());
        assertTrue(err.startsWith("minigolf: "), what + ": " + err);
        assertFalse(err.contains("internal error") || err.contains("Exception"), what + ": " + err);
        assertTrue(err.contains(expected), what + ": expected '" + expected + "' in " + err);
    }

    @Test
    void everyCommandRefusesBrokenCourseFilesInOneLine() throws IOException, InterruptedException {
        Path binary = dir.resolve("binary.json");
        Files.write(binary, new byte[]{(byte) 0x89, 'P', 'N', 'G', 0, 0, 1});
        Path utf16 = dir.resolve("utf16.json");
        Files.write(utf16, "{\"format\": 1}".getBytes(StandardCharsets.UTF_16));
        Path blank = dir.resolve("blank.json");
        Files.writeString(blank, "   \n  ");
        Path zero = dir.resolve("zero.json");
        Files.createSymbolicLink(zero, Path.of("/dev/zero"));
        Path fifo = dir.resolve("fifo.json");
        boolean haveFifo = new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0;
        Path bad = dir.resolve("bad.json");
        Files.writeString(bad, "{\"format\": 1, \"name\": \"x\"}");
        Path unreadable = dir.resolve("unreadable.json");
        Files.writeString(unreadable, "{}");
        boolean canMakeUnreadable = unreadable.toFile().setReadable(false, false) && !Files.isReadable(unreadable);

        for (String command : COURSE_COMMANDS) {
            assertOneLineExit2(CliRun.of(args(command, dir.resolve("missing.json").toString())), command + " missing", "no such file");
            assertOneLineExit2(CliRun.of(args(command, dir.toString())), command + " folder", "is a directory");
            assertOneLineExit2(CliRun.of(args(command, binary.toString())), command + " binary", "binary data");
            assertOneLineExit2(CliRun.of(args(command, utf16.toString())), command + " utf16", "UTF-16 text");
            assertOneLineExit2(CliRun.of(args(command, blank.toString())), command + " blank", "only whitespace");
            assertOneLineExit2(CliRun.of(args(command, zero.toString())), command + " /dev/zero", "not a regular file");
            if (haveFifo) assertOneLineExit2(CliRun.of(args(command, fifo.toString())), command + " fifo", "not a regular file");
            assertOneLineExit2(CliRun.of(args(command, bad.toString())), command + " invalid", "terrain: missing required field");
            if (canMakeUnreadable) {
                assertOneLineExit2(CliRun.of(args(command, unreadable.toString())), command + " unreadable", "permission denied");
            }
        }
    }

    @Test
    void badNumbersAndFoldersGiveOneLine() throws IOException {
        String lake = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "lake.json").toString();
        List<String[]> cases = new ArrayList<>();
        cases.add(new String[]{"simulate", lake, "--velocity", "x,1"});
        cases.add(new String[]{"simulate", lake, "--velocity", "1,0", "--dt", "-1"});
        cases.add(new String[]{"simulate", lake, "--velocity", "NaN,0"});
        cases.add(new String[]{"simulate", lake, "--velocity", "99,0"});
        cases.add(new String[]{"bench-physics", lake, "--shots", "-5"});
        cases.add(new String[]{"bench-physics", lake, "--shots", "many"});
        cases.add(new String[]{"bench-accuracy", lake, "--dt", "0"});
        cases.add(new String[]{"solve", lake, "--max-strokes", "0"});
        cases.add(new String[]{"solve", lake, "--bot", "nobody"});
        cases.add(new String[]{"render", lake, "--out", dir.resolve("x.png").toString(), "--size", "0x0"});
        cases.add(new String[]{"render", lake, "--out", dir.resolve("x.png").toString(), "--quality", "ultra"});
        cases.add(new String[]{"bench-render", lake, "--frames", "-1"});
        cases.add(new String[]{"play", lake, "--frames", "-3"});
        cases.add(new String[]{"play", lake, "--time-scale", "-1", "--frames", "1"});
        cases.add(new String[]{"edit", "--size", "axb", "--frames", "1"});
        cases.add(new String[]{"edit", "--spacing", "0", "--frames", "1"});
        cases.add(new String[]{"experiment", "--suite", dir.resolve("missing").toString(), "--out", dir.resolve("o").toString()});
        cases.add(new String[]{"experiment", "--suite", lake, "--out", dir.resolve("o").toString()});
        cases.add(new String[]{"experiment", "--suite", dir.toString(), "--out", dir.resolve("o").toString(), "--seeds", "0"});
        cases.add(new String[]{"experiment-merge", dir.resolve("missing").toString(), "--out", dir.resolve("m").toString()});
        cases.add(new String[]{"experiment-merge", lake, "--out", dir.resolve("m").toString()});
        cases.add(new String[]{"experiment-merge", dir.toString(), "--out", dir.resolve("m2").toString()});
        cases.add(new String[]{"bench-limits", "--dir", lake});
        cases.add(new String[]{"bench-editor", "--dabs", "-1"});
        cases.add(new String[]{"bench-editor", "--radius", "0"});
        cases.add(new String[]{"no-such-command"});
        for (String[] c : cases) assertOneLineExit2(CliRun.of(c), String.join(" ", c), "");
    }

    /** A heap too small for a course: the out-of-memory error ends as one line with exit code 2, not a stack trace. */
    @Test
    void runningOutOfMemoryWhileLoadingGivesOneLine() throws Exception {
        String grid = LimitCases.grid(dir).toString(); // 512 x 512 with both friction grids, 3.7 MB
        List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx20m",
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "minigolf.Main",
                "simulate", grid, "--velocity", "1,0");
        Path err = dir.resolve("oom.txt");
        Process p = new ProcessBuilder(cmd).redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS));
        String text = Files.readString(err).strip();
        assertEquals(2, p.exitValue(), text);
        assertFalse(text.contains("\n") || text.contains("\tat "), text);
        assertTrue(text.startsWith("minigolf: ") && text.contains("memory"), text);
    }

    /**
     * Without a display the commands that need a visible window say so in one line (a child process: DISPLAY is
     * read at start). render and bench-render draw off-screen through EGL instead: HeadlessCommandsTest covers them.
     */
    @Test
    void windowCommandsWithoutADisplayGiveOneLine() throws Exception {
        String lake = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "lake.json").toString();
        String[][] cases = {
                {"play", lake, "--frames", "1"},
                {"edit", lake, "--frames", "1"},
        };
        for (String[] c : cases) {
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-Xmx256m", "-Dminigolf.configDir=" + dir.resolve("cfg"), "-cp", System.getProperty("java.class.path"), "minigolf.Main"));
            cmd.addAll(List.of(c));
            ProcessBuilder pb = new ProcessBuilder(cmd);
            pb.environment().remove("DISPLAY");
            pb.environment().remove("WAYLAND_DISPLAY");
            Path runtime = Files.createDirectories(dir.resolve("xdg"));
            runtime.toFile().setExecutable(true, true);
            pb.environment().put("XDG_RUNTIME_DIR", runtime.toString());
            Path err = dir.resolve("err.txt");
            pb.redirectError(err.toFile()).redirectOutput(ProcessBuilder.Redirect.DISCARD);
            Process p = pb.start();
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), String.join(" ", c) + " finished");
            String text = Files.readString(err).strip();
            // GLFW itself may print its own line about XDG_RUNTIME_DIR; ours is the last and only "minigolf:" one.
            List<String> ours = text.lines().filter(l -> l.startsWith("minigolf:")).toList();
            assertEquals(2, p.exitValue(), String.join(" ", c) + ": " + text);
            assertEquals(1, ours.size(), text);
            assertTrue(ours.get(0).startsWith("minigolf: no display for a window"), ours.get(0));
            assertFalse(text.contains("\tat "), text);
        }
    }
}
