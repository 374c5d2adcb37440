package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import minigolf.cli.MinigolfCommand;
import minigolf.game.SettingsStore;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The editor never loses a recovery file: an earlier session's file is held until the user chooses. */
class RecoveryTest {
    @TempDir
    Path dir;

    private static Path flat() {
        return Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json");
    }

    @Test
    void anEarlierSessionsFileIsHeldUntilTheUserChooses() throws Exception {
        CourseEditor editor = CourseEditor.open(flat());
        Recovery first = new Recovery(dir);
        first.save(editor.toCourse(), flat());
        String saved = Files.readString(first.file());

        // The next session: the file is held, autosaves do not replace it, a clean close keeps it.
        Recovery next = new Recovery(dir);
        assertTrue(next.start());
        editor.setName("Changed");
        assertTrue(editor.isDirty());
        assertFalse(next.autosave(editor, 1000));
        next.closeCleanly();
        assertEquals(saved, Files.readString(next.file()));

        // Recovered: from now on autosaves replace it, and a clean close removes it.
        Recovery again = new Recovery(dir);
        assertTrue(again.start());
        assertEquals("Flat", again.load().course().name());
        again.release();
        assertTrue(again.autosave(editor, 1000));
        assertTrue(Files.readString(again.file()).contains("Changed"));
        again.closeCleanly();
        assertFalse(Files.exists(again.file()));
        assertFalse(new Recovery(dir).start());
    }

    /**
     * The editor killed during Ctrl+S leaves the new course in a hidden ".name.hex.tmp" beside the
     * file: the next time the file is opened the newest whole one is offered as the recovery file and
     * every one of them is removed; cut-short ones and ones that hold the file's own content offer nothing.
     */
    @Test
    void anUnfinishedSaveBesideTheFileIsOfferedAndRemoved() throws Exception {
        Path folder = Files.createDirectories(dir.resolve("courses"));
        Path file = folder.resolve("mine.json");
        Files.copy(flat(), file);
        CourseEditor editor = CourseEditor.open(file);
        editor.setName("Newest edits");
        String newest = minigolf.course.CourseWriter.toJson(editor.toCourse());
        editor.setName("Older edits");
        String older = minigolf.course.CourseWriter.toJson(editor.toCourse());
        Path a = temporary(folder, ".mine.json.0badc0de.tmp", older, 120);
        Path b = temporary(folder, ".mine.json.1234abcd.tmp", newest, 90);
        Path cut = temporary(folder, ".mine.json.77.tmp", newest.substring(0, newest.length() / 2), 60); // newest, cut short
        Path young = temporary(folder, ".mine.json.5eed.tmp", newest, 0); // perhaps still being written
        Path other = temporary(folder, ".other.json.abc.tmp", newest, 120); // another file's: not this file's to take

        Recovery recovery = new Recovery(dir.resolve("config"));
        assertFalse(recovery.start());
        assertTrue(recovery.adoptUnfinishedSave(file));
        assertTrue(recovery.isHeld(), "held until the user chooses");
        Recovery.Recovered r = recovery.load();
        assertEquals("Newest edits", r.course().name());
        assertEquals(file.toAbsolutePath(), r.originalFile());
        for (Path p : new Path[]{a, b, cut}) assertFalse(Files.exists(p), p + " removed");
        assertTrue(Files.exists(young) && Files.exists(other));
        assertEquals(Files.readString(flat()), Files.readString(file), "the file itself is untouched");

        // A waiting recovery file is never replaced: the temporaries stay for a later start.
        Path again = temporary(folder, ".mine.json.99.tmp", older, 60);
        assertFalse(recovery.adoptUnfinishedSave(file));
        assertTrue(Files.exists(again));
        // Once chosen, a temporary that holds the file's own content (the save finished its bytes) offers nothing.
        recovery.clear();
        temporary(folder, again.getFileName().toString(), Files.readString(file), 60);
        assertFalse(recovery.adoptUnfinishedSave(file));
        assertFalse(Files.exists(again), "removed: nothing in it that the file does not hold");
        assertFalse(recovery.exists());
    }

    private static Path temporary(Path folder, String name, String content, int ageSeconds) throws Exception {
        Path t = folder.resolve(name);
        Files.writeString(t, content);
        Files.setLastModifiedTime(t, FileTime.fromMillis(System.currentTimeMillis() - ageSeconds * 1000L));
        return t;
    }

    @Test
    void staleTemporaryFilesAreRemovedAtStartYoungOnesKept() throws Exception {
        Path stale = dir.resolve(".editor-recovery.json.1f2e3d.tmp");
        Path young = dir.resolve(".editor-recovery.json.abc123.tmp");
        Path other = dir.resolve("notes.tmp");
        for (Path p : new Path[]{stale, young, other}) Files.writeString(p, "{\"format\": 1");
        Files.setLastModifiedTime(stale, FileTime.fromMillis(System.currentTimeMillis() - 3_600_000));
        Files.setLastModifiedTime(other, FileTime.fromMillis(System.currentTimeMillis() - 3_600_000));
        assertFalse(new Recovery(dir).start());
        assertFalse(Files.exists(stale), "a killed autosave's leftover");
        assertTrue(Files.exists(young), "may be another editor's autosave in progress");
        assertTrue(Files.exists(other), "not ours");
        assertEquals(0, new SettingsStore(dir).removeStaleTemporaries());
    }

    /** {@code minigolf edit COURSE --frames N} with a recovery file waiting keeps it and says so. */
    @Test
    @minigolf.render.NeedsDisplay
    void aScriptedEditKeepsTheRecoveryFileAndSaysSo() throws Exception {
        Path config = dir.resolve("config");
        Recovery earlier = new Recovery(config);
        CourseEditor unsaved = CourseEditor.open(flat());
        unsaved.setName("Unsaved work");
        earlier.save(unsaved.toCourse(), null);
        byte[] before = Files.readAllBytes(earlier.file());
        String previous = System.getProperty(SettingsStore.CONFIG_DIR_PROPERTY);
        PrintStream stderr = System.err;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        System.setProperty(SettingsStore.CONFIG_DIR_PROPERTY, config.toString());
        System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
        int code;
        StringWriter err = new StringWriter();
        try {
            code = MinigolfCommand.execute(new String[]{"edit", flat().toString(), "--frames", "3", "--keys", "D,D"},
                    new PrintWriter(new StringWriter()), new PrintWriter(err));
        } finally {
            System.setErr(stderr);
            if (previous == null) System.clearProperty(SettingsStore.CONFIG_DIR_PROPERTY);
            else System.setProperty(SettingsStore.CONFIG_DIR_PROPERTY, previous);
        }
        assertEquals(0, code, err.toString());
        assertTrue(java.util.Arrays.equals(before, Files.readAllBytes(earlier.file())), "the recovery file is unchanged");
        String said = captured.toString(StandardCharsets.UTF_8);
        assertTrue(said.contains("minigolf: a recovery file from an editor session that did not close is kept: "
                + earlier.file()), said);
    }
}
