package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import minigolf.course.CourseException;
import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;

/** The fuzz tests' one load-or-refuse step fails them for a loader that throws or shows a trace, and only then. */
class FuzzChecksTest {
    private static final String FILE = "/tmp/case-7.json";

    private static String failureOf(FuzzChecks.Load load) throws IOException {
        FuzzChecks checks = new FuzzChecks();
        checks.started();
        checks.loadOrRefuse("round garbage", "round seed 7", FILE + ": ", load);
        return assertThrows(AssertionFailedError.class, () -> checks.report("checks", 1)).getMessage();
    }

    private static void passes(FuzzChecks.Load load) throws IOException {
        FuzzChecks checks = new FuzzChecks();
        checks.started();
        checks.loadOrRefuse("round garbage", "round seed 7", FILE + ": ", load);
        assertDoesNotThrow(() -> checks.report("checks", 1));
    }

    @Test
    void aLoadedCaseAndAOneLineRefusalNamingTheFilePass() throws IOException {
        passes(() -> { });
        passes(() -> {
            throw new CourseException(FILE, "holes[0].par", "must be a whole number, got \"x\"");
        });
    }

    @Test
    void aLoaderThatThrowsAnythingElseFailsTheTest() throws IOException {
        String m = failureOf(() -> {
            throw new IllegalStateException("no stroke is rolling");
        });
        assertTrue(m.contains("round seed 7: threw java.lang.IllegalStateException: no stroke is rolling"), m);
        assertTrue(failureOf(() -> {
            throw new StackOverflowError();
        }).contains("threw java.lang.StackOverflowError"));
    }

    @Test
    void aRefusalThatShowsATraceOrAnotherFileFailsTheTest() throws IOException {
        String trace = failureOf(() -> {
            throw new CourseException(FILE, null, "java.lang.NumberFormatException: For input string: \"x\"");
        });
        assertTrue(trace.contains("round seed 7: an internal error"), trace);
        String elsewhere = failureOf(() -> {
            throw new CourseException("/etc/passwd", null, "Unrecognized token 'root'");
        });
        assertTrue(elsewhere.contains("does not start with " + FILE), elsewhere);
    }

    @Test
    void anIoErrorOfTheTestsOwnFilesEndsTheTest() {
        FuzzChecks checks = new FuzzChecks();
        assertThrows(IOException.class, () -> checks.loadOrRefuse("round garbage", "round seed 7", FILE + ": ", () -> {
            throw new IOException("disk full");
        }));
    }
}
