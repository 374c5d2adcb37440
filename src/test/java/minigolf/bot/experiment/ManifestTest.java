package minigolf.bot.experiment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** experiment.json: what the fingerprint covers, and that a hand-edited manifest is caught. */
class ManifestTest {
    private static final List<Manifest.CourseFile> COURSES = List.of(
            new Manifest.CourseFile("flat", Manifest.sha256("{\"a\":1}".getBytes(StandardCharsets.UTF_8))),
            new Manifest.CourseFile("lake", Manifest.sha256("{\"b\":2}".getBytes(StandardCharsets.UTF_8))));
    private static final Manifest.Options OPTIONS = Manifest.Options.of(List.of("planner", "newton"), 5, 20000, 10);

    @Test
    void theFingerprintCoversProgramOptionsAndCourseContentsButNotTheShard() {
        Manifest m = Manifest.of("minigolf 0.1.0", OPTIONS, COURSES);
        assertEquals(2 * 2 * 5, m.runs());
        // SHA-256 of "{"a":1}", computed independently (sha256sum).
        assertEquals("015abd7f5cc57a2dd94b7590f04ad8084273905ee33ec5cebeae62276a97f862", COURSES.get(0).sha256());
        assertEquals(m.fingerprint(), m.forShard(new Shard(2, 4)).fingerprint());
        assertEquals(m.fingerprint(), Manifest.of("minigolf 0.1.0", OPTIONS, COURSES).fingerprint());
        assertNotEquals(m.fingerprint(), Manifest.of("minigolf 0.1.1", OPTIONS, COURSES).fingerprint());
        assertNotEquals(m.fingerprint(), Manifest.of("minigolf 0.1.0",
                Manifest.Options.of(List.of("planner", "newton"), 5, 20001, 10), COURSES).fingerprint());
        assertNotEquals(m.fingerprint(), Manifest.of("minigolf 0.1.0",
                Manifest.Options.of(List.of("newton", "planner"), 5, 20000, 10), COURSES).fingerprint());
        Manifest changedCourse = Manifest.of("minigolf 0.1.0", OPTIONS, List.of(COURSES.get(0),
                new Manifest.CourseFile("lake", Manifest.sha256("{\"b\":3}".getBytes(StandardCharsets.UTF_8)))));
        assertNotEquals(m.fingerprint(), changedCourse.fingerprint());
        assertEquals("different contents of course file(s) lake", m.differences(changedCourse));
        assertEquals("", m.differences(m.forShard(new Shard(0, 2))));
    }

    @Test
    void theNoiseGridAndHiddenFrictionArePartOfTheExperiment() {
        Manifest m = Manifest.of("minigolf 0.1.0", OPTIONS, COURSES);
        Manifest noisy = Manifest.of("minigolf 0.1.0", new Manifest.Options(List.of("planner", "newton"), 5, 20000, 10,
                List.of(0.0, 0.01), List.of(0.0, 0.05, 0.1), false), COURSES);
        Manifest hidden = Manifest.of("minigolf 0.1.0", new Manifest.Options(List.of("planner", "newton"), 5, 20000, 10,
                List.of(0.0), List.of(0.0), true), COURSES);
        assertEquals(2 * 6 * 2 * 5, noisy.runs(), "courses x noise cells x bots x seeds");
        assertNotEquals(m.fingerprint(), noisy.fingerprint());
        assertNotEquals(m.fingerprint(), hidden.fingerprint());
        assertTrue(m.differences(noisy).contains("--noise-position 0.0,0.01 --noise-velocity 0.0,0.05,0.1"),
                m.differences(noisy));
        assertTrue(m.differences(hidden).endsWith("--hide-friction against --bots planner,newton --seeds 5 --budget 20000"
                + " --max-strokes 10"), m.differences(hidden));
        // Run 0 of each cell: position noise outer, velocity inner.
        assertEquals(new minigolf.bot.NoiseModel(0.01, 0.05), noisy.plan().run(4 * 2 * 5).noise());
    }

    @Test
    void aManifestRoundTripsAndAHandEditIsCaught(@TempDir Path dir) throws IOException {
        assertNull(Manifest.read(dir));
        Manifest m = Manifest.of("minigolf 0.1.0", OPTIONS, COURSES).forShard(new Shard(1, 3));
        m.write(dir);
        assertEquals(m, Manifest.read(dir));
        Path file = dir.resolve(Manifest.FILE_NAME);
        Files.writeString(file, Files.readString(file).replace("\"seeds\" : 5", "\"seeds\" : 6"));
        assertEquals(file + ": the fingerprint does not match the contents (edited by hand?)",
                assertThrows(ExperimentException.class, () -> Manifest.read(dir)).getMessage());
        Files.writeString(file, "{ \"format\": 1, ");
        assertTrue(assertThrows(ExperimentException.class, () -> Manifest.read(dir)).getMessage()
                .startsWith(file + ": not a readable experiment manifest: "));
    }
}
