package minigolf.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import static org.junit.jupiter.api.Assertions.*;

/** render and bench-render (need xvfb-run for the GL parts). */
class RenderCommandTest {
    private static final Path COURSES = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses");

    private static CliRun run(String... args) {
        return CliRun.of(args);
    }

    private static String course(String name) {
        return COURSES.resolve(name).toString();
    }

    @Test
    void renderWritesAPngOfTheAskedSizeForBothViews(@TempDir Path dir) throws Exception {
        for (String view : new String[]{"orbit", "top"}) {
            Path png = dir.resolve("sub/" + view + ".png");
            CliRun r = run("render", course("lake.json"), "--out", png.toString(), "--size", "320x200", "--view", view);
            assertEquals(0, r.code(), r.err());
            byte[] bytes = Files.readAllBytes(png);
            // PNG signature, then the IHDR chunk's width and height (big-endian).
            assertEquals((byte) 0x89, bytes[0]);
            assertEquals("PNG", new String(bytes, 1, 3, "US-ASCII"));
            assertEquals(320, java.nio.ByteBuffer.wrap(bytes, 16, 4).getInt());
            assertEquals(200, java.nio.ByteBuffer.wrap(bytes, 20, 4).getInt());
        }
    }

    @Test
    void badRenderInputIsOneLineAndExitCodeTwo(@TempDir Path dir) throws Exception {
        String out = dir.resolve("x.png").toString();
        String[][] cases = {
                {"render", course("lake.json"), "--out", out, "--size", "12x12"},
                {"render", course("lake.json"), "--out", out, "--size", "wide"},
                {"render", course("lake.json"), "--out", dir.resolve("x.jpg").toString()},
                {"render", course("lake.json"), "--out", dir.toString() + "/"},
                {"render", dir.resolve("missing.json").toString(), "--out", out},
                {"bench-render", course("lake.json"), "--frames", "0"},
                {"bench-render", course("lake.json"), "--size", "100"},
        };
        for (String[] args : cases) {
            CliRun r = run(args);
            assertEquals(2, r.code(), String.join(" ", args) + ": " + r.err());
            assertTrue(r.err().startsWith("minigolf: "), r.err());
            assertEquals(1, r.err().strip().lines().count(), "not one line: " + r.err());
        }
        CliRun badView = run("render", course("lake.json"), "--out", out, "--view", "side");
        assertEquals(2, badView.code());
        assertTrue(badView.err().contains("--view"), badView.err());
        assertFalse(Files.exists(Path.of(out)), "a picture was written despite the errors");
    }

    @Test
    void benchRenderPrintsFramesMillisecondsAndTheRenderer() throws Exception {
        CliRun r = run("bench-render", course("lake.json"), "--frames", "5", "--size", "320x200");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        assertEquals(5, json.get("frames").asInt());
        assertTrue(json.get("msPerFrame").asDouble() > 0, r.out());
        assertFalse(json.get("renderer").asText().isBlank(), r.out());
        assertEquals("320x200", json.get("size").asText());
    }

    @Test
    @minigolf.render.NeedsDisplay
    void playTimingTimesTheRealGameLoop() throws Exception {
        CliRun r = run("play", course("flat.json"), "--players", "Ann", "--frames", "24", "--timing");
        assertEquals(0, r.code(), r.err());
        JsonNode json = new ObjectMapper().readTree(r.out());
        // 24 frames, the first quarter warm-up: passes 6 to 23 bound 17 timed frames.
        assertEquals(17, json.get("frames").asInt(), r.out());
        assertTrue(json.get("msPerFrame").asDouble() > 0, r.out());
        assertTrue(json.get("cpuMsPerFrame").asDouble() >= 0, r.out());
        assertEquals("Flat", json.get("course").asText());
        assertFalse(json.get("renderer").asText().isBlank(), r.out());
        CliRun tooFew = run("play", course("flat.json"), "--frames", "3", "--timing");
        assertEquals(2, tooFew.code());
        assertTrue(tooFew.err().contains("--timing needs --frames"), tooFew.err());
    }
}
