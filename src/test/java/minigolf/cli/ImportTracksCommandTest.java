package minigolf.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ImportTracksCommandTest {
    /** A frame of blocks, the start left, the hole right (tracks written here, from the format description). */
    static final String MAP = "BAQQ48D"                                                    // top row of blocks
            + "BAQQ" + "BAAA" + "46D" + "BAQQ"                                                 // row 1
            + "490E"                                                                            // rows 2..11 as row 1
            + "BAQQ" + "BAAA" + "DD" + "CAA" + "BAAA" + "38D" + "CBA" + "BAAA" + "DD" + "BAQQ" // row 12: start x 4, hole x 44
            + "BAQQ" + "BAAA" + "46D" + "BAQQ" + "490E"                                         // rows 13..23
            + "BAQQ" + "48D";                                                                   // bottom row

    static String track(String name, String data) {
        return "V 1\nA Tester\nN " + name + "\nT " + data + "\nI 20,90,3,2\n";
    }

    @Test
    void importsTracksAndListsThemWithTheirStatistics(@TempDir Path dir) throws Exception {
        Path in = dir.resolve("tracks"), out = dir.resolve("out");
        Files.createDirectories(in.resolve("basic"));
        Files.createDirectories(in.resolve("long"));
        Files.writeString(in.resolve("basic").resolve("Tester-One.track"), track("One", MAP));
        Files.writeString(in.resolve("long").resolve("Tester-One.track"), track("One", MAP)); // V1: one copy per category
        Files.writeString(in.resolve("long").resolve("Tester-Two.track"), track("Two: the sequel", MAP));
        CliRun r = CliRun.of("import-tracks", in.toString(), "--out", out.toString(), "--no-images");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err());
        JsonNode summary = r.json();
        assertEquals(2, summary.get("imported").asInt());
        assertEquals(0, summary.get("failed").asInt());
        assertEquals("built-in approximation", summary.get("shapes").asText());
        JsonNode index = new ObjectMapper().readTree(out.resolve("index.json").toFile());
        JsonNode one = index.get("tracks").get(0);
        assertEquals("One", one.get("name").asText());
        assertEquals("Tester", one.get("author").asText());
        assertEquals("[\"basic\",\"long\"]", one.get("categories").toString());
        assertEquals(20, one.get("plays").asInt());
        assertEquals(4.5, one.get("averageStrokes").asDouble(), 1e-12);
        assertEquals(3, one.get("bestStrokes").asInt());
        assertEquals(2, one.get("playersWithBest").asInt());
        assertEquals("courses/Tester-One/course.json", one.get("course").asText());
        assertEquals("courses/Tester-Two__the_sequel/course.json", index.get("tracks").get(1).get("course").asText());
        World w = World.load(out.resolve("courses/Tester-One/course.json"));
        assertEquals("One", w.course().name());
    }

    /** The imported courses are a suite for experiment (folders holding a course.json), and classic-report reads both. */
    @Test
    void experimentAndReportOnTheImport(@TempDir Path dir) throws Exception {
        Path in = dir.resolve("tracks"), out = dir.resolve("out"), exp = dir.resolve("exp");
        Files.createDirectories(in);
        Files.writeString(in.resolve("a.track"), track("Alpha", MAP));
        Files.writeString(in.resolve("b.track"), track("Beta", MAP));
        assertEquals(0, CliRun.of("import-tracks", in.toString(), "--out", out.toString(), "--no-images").code());
        CliRun e = CliRun.of("experiment", "--suite", out.resolve("courses").toString(), "--out", exp.toString(),
                "--bots", "planner", "--seeds", "1", "--threads", "1", "--max-strokes", "3");
        assertEquals(0, e.code(), e.err());
        String results = Files.readString(exp.resolve("results.csv"));
        assertTrue(results.contains("\nTester-Alpha,planner,1,") && results.contains("\nTester-Beta,planner,1,"), results);
        CliRun r = CliRun.of("classic-report", out.toString(), "--results", exp.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("Import: 2 of 2 tracks imported (2/2 = 100.0%; a file not imported counts as one track), 2 of 2 load"), r.out());
        assertTrue(r.out().contains("| planner | 2 | 2 | "), r.out());
    }

    /** A malformed track: one line naming it, exit 2, nothing written for it; the others are imported. */
    @Test
    void aMalformedTrackIsOneLineAndExitTwo(@TempDir Path dir) throws Exception {
        Path in = dir.resolve("tracks"), out = dir.resolve("out");
        Files.createDirectories(in);
        Files.writeString(in.resolve("good.track"), track("Good", MAP));
        Files.writeString(in.resolve("bad.track"), track("Bad", MAP.replace("CBA", "CcA")));
        Files.writeString(in.resolve("nohole.track"), track("No hole", MAP.replace("CBA", "BAAA")));
        CliRun r = CliRun.of("import-tracks", in.toString(), "--out", out.toString(), "--no-images");
        assertEquals(2, r.code());
        String[] lines = r.err().strip().split("\n");
        assertEquals(2, lines.length, r.err());
        assertEquals("minigolf: not imported: bad.track: line 4 (T): tile 633 (x 44, y 12): special block 28 does not exist (0-27)",
                lines[0]);
        assertEquals("minigolf: not imported: nohole.track: No hole: the map has no hole", lines[1]);
        assertEquals(1, r.json().get("imported").asInt());
        assertEquals(2, r.json().get("failed").asInt());
        try (Stream<Path> s = Files.list(out.resolve("courses"))) {
            assertEquals("[Tester-Good]", s.map(p -> p.getFileName().toString()).sorted().toList().toString());
        }
        JsonNode failed = new ObjectMapper().readTree(out.resolve("index.json").toFile()).get("failed");
        assertEquals(2, failed.size());
        assertEquals("bad.track", failed.get(0).get("source").asText());
    }

    /** One malformed file given alone: one line, exit 2, no course written. */
    @Test
    void aSingleMalformedFile(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.track"), out = dir.resolve("out");
        Files.writeString(bad, "V 1\nA x\nN y\nT BAAA\n");
        CliRun r = CliRun.of("import-tracks", bad.toString(), "--out", out.toString(), "--no-images");
        assertEquals(2, r.code());
        assertEquals(1, r.err().strip().split("\n").length, r.err());
        assertTrue(r.err().contains("bad.track: line 4 (T): tile 2 (x 1, y 0): the map data ends early"), r.err());
        try (Stream<Path> s = Files.walk(out)) {
            assertFalse(s.anyMatch(p -> p.getFileName().toString().equals("course.json")));
        }
    }

    @Test
    void usageErrors(@TempDir Path dir) {
        CliRun missing = CliRun.of("import-tracks", dir.resolve("none").toString(), "--out", dir.resolve("o").toString());
        assertEquals(2, missing.code());
        assertTrue(missing.err().strip().endsWith("none: no such file or folder"), missing.err());
        assertEquals(1, missing.err().strip().split("\n").length);
        CliRun tile = CliRun.of("import-tracks", dir.toString(), "--tile", "0", "--out", dir.resolve("o").toString());
        assertEquals(2, tile.code());
        assertTrue(tile.err().contains("--tile: must be in (0, 100] metres, got 0.0"), tile.err());
        CliRun images = CliRun.of("import-tracks", dir.toString(), "--images", dir.resolve("nope").toString(),
                "--out", dir.resolve("o").toString());
        assertEquals(2, images.code());
        assertTrue(images.err().contains("--images: "), images.err());
    }
}
