package minigolf.app;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import minigolf.course.CourseException;
import minigolf.physics.World;

/** Opens the game on the default course, which ships inside the jar. */
public final class GameLauncher {
    /** The course {@code gradle run} and a bare {@code minigolf} open. */
    public static final String DEFAULT_COURSE = "/courses/lake.json";

    private GameLauncher() {
    }

    public static void playDefaultCourse() {
        World world = loadBundled(DEFAULT_COURSE);
        GameWindow.show(world, null);
    }

    /** Loads a course that is packaged on the classpath (the courses/ folder is copied into the jar). */
    public static World loadBundled(String resource) {
        try (InputStream in = GameLauncher.class.getResourceAsStream(resource)) {
            if (in == null) throw new IllegalStateException("the game's jar has no " + resource);
            return World.parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), resource);
        } catch (IOException | CourseException e) {
            throw new IllegalStateException("cannot load the bundled course " + resource + ": " + e.getMessage(), e);
        }
    }
}
