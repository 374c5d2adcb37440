package minigolf.game;

import minigolf.course.CourseException;

/**
 * A saved game (or the settings file) could not be read or written. One line:
 * {@code <file>: <field path>: <problem>}, as for course files, so the command line reports it
 * the same way (exit code 2).
 */
public class SaveGameException extends CourseException {
    private static final long serialVersionUID = 1L;

    public SaveGameException(String sourceName, String path, String problem) {
        super(sourceName, path, problem);
    }

    public SaveGameException(String sourceName, String path, String problem, Throwable cause) {
        super(sourceName, path, problem, cause);
    }
}
