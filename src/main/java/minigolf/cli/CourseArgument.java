package minigolf.cli;

import java.nio.file.Path;
import minigolf.course.CourseException;
import minigolf.physics.World;

/** Loads the course file a command names, turning loader errors into user errors. */
final class CourseArgument {
    private CourseArgument() {
    }

    static World load(Path file) {
        try {
            return World.load(file);
        } catch (CourseException e) {
            throw new UserError(e.getMessage());
        }
    }
}
