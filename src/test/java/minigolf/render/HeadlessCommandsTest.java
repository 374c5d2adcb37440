package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
 * The command line in a fresh JVM with no display in its environment (DISPLAY, WAYLAND_DISPLAY and
 * XDG_RUNTIME_DIR removed), as over SSH or in a container: render works through EGL with nothing on
 * stderr; with no OpenGL at all it is one line and exit code 2.
 */
class HeadlessCommandsTest {
    @TempDir
    Path dir;

    private record Result(int code, String out, String err) {
    }

    private static Result run(List<String> jvmOptions, String... args) throws IOException, InterruptedException {
        return run(jvmOptions, java.util.Map.of(), args);
    }

    private static Result run(List<String> jvmOptions, java.util.Map<String, String> env, String... args)
            throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        command.add("-Xmx512m");
        command.addAll(jvmOptions);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add("minigolf.Main");
        command.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(command).directory(projectDir().toFile());
        pb.environment().remove("DISPLAY");
        pb.environment().remove("WAYLAND_DISPLAY");
        pb.environment().remove("XDG_RUNTIME_DIR");
        pb.environment().remove("MINIGOLF_GL");
        pb.environment().putAll(env);
        Process p = pb.start();
        p.getOutputStream().close();
        var out = p.getInputStream().readAllBytes();
        var err = p.getErrorStream().readAllBytes();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the command did not finish");
        return new Result(p.exitValue(), new String(out, StandardCharsets.UTF_8), new String(err, StandardCharsets.UTF_8));
    }

    private static Path projectDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."));
    }

    /** The EGL device platform (NVIDIA's path; Mesa offers it too) renders and exits 0 after its teardown. */
    @Test
    void renderOnTheEglDevicePlatformExitsZero() throws Exception {
        Path png = dir.resolve("device.png");
        Result r = run(List.of(), java.util.Map.of("MINIGOLF_EGL", "device"), "render", "courses/lake.json", "--out", png.toString(),
                "--size", "160x100");
        org.junit.jupiter.api.Assumptions.assumeFalse(r.err().contains("no device platform"), "this EGL has no device platform");
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.size(png) > 1000);
    }

    /** bench-render given a round times every hole and writes a table with the load average. */
    @Test
    void benchRenderOfARoundTimesEveryHoleAndWritesATable() throws Exception {
        // A round names its courses relative to its own folder (round files are confined to it and its siblings).
        Path holes = Files.createDirectories(dir.resolve("worlds/canyon")), rounds = Files.createDirectories(dir.resolve("rounds"));
        for (String hole : List.of("01-trailhead.json", "09-butte-bowl.json")) {
            Files.copy(projectDir().resolve("courses/worlds/canyon").resolve(hole), holes.resolve(hole));
        }
        Path round = rounds.resolve("two.json");
        Files.writeString(round, "{\"format\": 1, \"name\": \"Two\", \"holes\": [{\"course\": \"../worlds/canyon/01-trailhead.json\","
                + " \"par\": 2}, {\"course\": \"../worlds/canyon/09-butte-bowl.json\", \"par\": 2}]}");
        Path table = dir.resolve("table.md");
        Result r = run(List.of(), "bench-render", round.toString(), "--frames", "2", "--size", "160x100", "--quality", "software",
                "--table", table.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("\"holes\":[") && r.out().contains("\"course\":\"Trailhead\"") && r.out().contains("\"world\":\"canyon\""), r.out());
        String t = Files.readString(table);
        assertTrue(t.contains("| 1 | Trailhead | 2 |") && t.contains("| 2 | Butte Bowl | 2 |"), t);
        assertTrue(t.contains("load average") && t.contains("Slowest hole"), t);
    }

    @Test
    void renderWithoutADisplayWritesThePictureAndPrintsNothing() throws Exception {
        Path png = dir.resolve("lake.png");
        Result r = run(List.of(), "render", "courses/lake.json", "--out", png.toString(), "--size", "160x100");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
        assertEquals("", r.out());
        Pixels px = Pixels.read(png);
        assertEquals(160, px.width());
        assertEquals(100, px.height());
        // The lake is in the middle of the picture, behind the ball: some water pixels must be there.
        int water = 0;
        for (int y = 0; y < 100; y++) for (int x = 0; x < 160; x++) if (px.isWater(x, y)) water++;
        assertTrue(water > 50, water + " water pixels");
    }

    @Test
    void noOpenGlAtAllIsOneLineAndExitCodeTwo() throws Exception {
        // LWJGL loads EGL from this file name: a missing one stands for a machine without libEGL.
        Result r = run(List.of("-Dorg.lwjgl.egl.libname=/nonexistent/libEGL.so.1"),
                "render", "courses/lake.json", "--out", "nothing.png");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().startsWith("minigolf: no OpenGL available: no display (DISPLAY is unset) and no"
                + " display-less OpenGL: no libEGL"), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertTrue(Files.notExists(projectDir().resolve("nothing.png")));
    }

    @Test
    void theGameWindowWithoutADisplayIsOneLineAndExitCodeTwo() throws Exception {
        Result r = run(List.of(), "play", "courses/flat.json");
        assertEquals(2, r.code(), r.err());
        assertEquals("minigolf: no display for a window (DISPLAY is unset; render and bench-render work without one)\n",
                r.err());
    }
}
