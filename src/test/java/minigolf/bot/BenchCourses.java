package minigolf.bot;

import java.nio.file.Path;
import minigolf.course.CourseException;
import minigolf.physics.World;

/** The benchmark suite's courses, loaded from the project folder. */
final class BenchCourses {
    static final Path DIR = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses").resolve("bench");

    private BenchCourses() {
    }

    static World load(String name) {
        try {
            return World.load(DIR.resolve(name + ".json"));
        } catch (CourseException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }
}
