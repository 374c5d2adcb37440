package minigolf.editor;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseLoader;
import minigolf.course.CourseWriter;
import minigolf.course.Limits;
import minigolf.io.AtomicFile;
import minigolf.io.TextFiles;

/**
 * The editor's autosave: the course being edited is written (atomically) to a recovery file in
 * the config folder every few seconds while it has unsaved changes, with the path of the file it
 * came from beside it. A clean close removes both; if they are still there at the next start the
 * editor crashed or was killed, and the editor offers the recovered course.
 */
public final class Recovery {
    /** Seconds between autosaves of a changed course. */
    public static final double INTERVAL_SECONDS = 10;

    private final Path course;
    private final Path origin;
    private double lastSave = Double.NEGATIVE_INFINITY;
    private long savedVersion = -1;
    /** A recovery file of an earlier session is waiting for the user's choice: never overwrite or remove it. */
    private boolean held;

    /** A recovered course and the file it was edited from (null for a course never saved). */
    public record Recovered(Course course, Path originalFile) {
    }

    public Recovery(Path directory) {
        this.course = directory.resolve("editor-recovery.json");
        this.origin = directory.resolve("editor-recovery.origin");
    }

    public Path file() {
        return course;
    }

    /**
     * At the start of a session: removes temporary files a killed autosave left behind and, if an
     * earlier session's recovery file is waiting, holds it (no autosave replaces it and
     * {@link #closeCleanly()} keeps it) until {@link #release()} or {@link #clear()}.
     *
     * @return whether a recovery file is waiting
     */
    public boolean start() {
        AtomicFile.removeStaleTemporaries(course.getParent());
        held = exists();
        return held;
    }

    /** Whether an earlier session's recovery file is being kept. */
    public boolean isHeld() {
        return held;
    }

    /** The user recovered the course: from now on autosaves may replace the file. */
    public void release() {
        held = false;
    }

    /** A clean close: the recovery file is removed unless an earlier session's file is still held. */
    public void closeCleanly() {
        if (!held) clear();
    }

    /** Writes the course now. */
    public void save(Course c, Path originalFile) throws IOException {
        Files.createDirectories(course.getParent());
        AtomicFile.write(origin, (originalFile == null ? "" : originalFile.toAbsolutePath().toString())
                .getBytes(StandardCharsets.UTF_8));
        AtomicFile.write(course, CourseWriter.toJson(c).getBytes(StandardCharsets.UTF_8));
    }

    /**
     * Autosaves if the editor has unsaved changes that are not in the recovery file yet and the
     * interval has passed since the last autosave. Returns whether it wrote.
     */
    public boolean autosave(CourseEditor editor, double nowSeconds) throws IOException {
        if (held || !editor.isDirty() || nowSeconds - lastSave < INTERVAL_SECONDS || savedVersion == editor.version()) return false;
        save(editor.toCourse(), editor.file());
        lastSave = nowSeconds;
        savedVersion = editor.version();
        return true;
    }

    /**
     * Temporary files of a save younger than this may belong to a save still being written (another
     * editor saving the same file); a save of the largest course (8 MiB) takes well under a second.
     */
    static final long UNFINISHED_SAVE_AGE_MILLIS = 5_000;

    /**
     * A save of {@code file} that did not finish (the editor killed during Ctrl+S) leaves the new
     * course in a hidden {@code .name.<hex>.tmp} beside it, where nothing would find it. The newest
     * such file that holds a whole course, other than the file's own, becomes the recovery file
     * (offered like a crashed session's, with {@code file} as its origin), unless one is already
     * waiting; then every one of them is removed (a cut-short one holds no course to offer).
     *
     * @return whether a recovery file is now waiting for the user's choice because of it
     */
    public boolean adoptUnfinishedSave(Path file) {
        if (file == null || held) return false; // a waiting recovery is never replaced; the files stay for the next start
        java.util.List<Path> temporaries = AtomicFile.temporariesOf(file, UNFINISHED_SAVE_AGE_MILLIS);
        if (temporaries.isEmpty()) return false;
        String current;
        try {
            current = Files.isRegularFile(file) ? TextFiles.read(file, Limits.COURSE_FILE_BYTES) : null;
        } catch (IOException e) {
            current = null;
        }
        Course newest = null;
        for (Path t : temporaries) {
            try {
                String json = TextFiles.read(t, Limits.COURSE_FILE_BYTES);
                if (json.equals(current)) break; // the newest whole save is the file itself: nothing new
                newest = CourseLoader.parse(json, file.toString());
                break;
            } catch (IOException | CourseException e) {
                // cut short or not a course: the next older one
            }
        }
        boolean adopted = false;
        if (newest != null) {
            try {
                save(newest, file);
                adopted = true;
            } catch (IOException e) {
                return false; // not kept elsewhere: the temporary files stay
            }
        }
        for (Path t : temporaries) {
            try {
                Files.deleteIfExists(t);
            } catch (IOException e) {
                // stays; offered or removed next time
            }
        }
        held = adopted;
        return adopted;
    }

    /** Whether a recovery file is waiting from an earlier session. */
    public boolean exists() {
        return Files.isRegularFile(course);
    }

    /** The recovered course; model files are looked up beside the original file. */
    public Recovered load() throws CourseException {
        Path original = null;
        try {
            String text = Files.isRegularFile(origin) ? TextFiles.read(origin, 64 * 1024).trim() : "";
            if (!text.isEmpty()) original = Path.of(text);
            String json = TextFiles.read(course, Limits.COURSE_FILE_BYTES);
            String source = original != null ? original.toString() : course.toString();
            return new Recovered(CourseLoader.parse(json, source), original);
        } catch (IOException | RuntimeException e) {
            throw new CourseException(course.toString(), null, "cannot read the recovery file: " + e.getMessage(), e);
        }
    }

    /** Removes the recovery file (after a clean close, or when the user declines it). */
    public void clear() {
        try {
            Files.deleteIfExists(course);
            Files.deleteIfExists(origin);
        } catch (IOException e) {
            // A stale recovery file is only offered again; nothing is lost.
        }
        savedVersion = -1;
        lastSave = Double.NEGATIVE_INFINITY;
        held = false;
    }
}
