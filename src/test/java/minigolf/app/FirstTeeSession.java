package minigolf.app;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.CourseException;
import minigolf.game.SettingsStore;
import minigolf.physics.World;

/** A play session on the first tee whose messages go to a list: for tests of what the game says. */
final class FirstTeeSession {
    private FirstTeeSession() {
    }

    /** The first tee (courses/holes/01-first-tee.json). */
    static World tee() throws CourseException {
        return World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/holes/01-first-tee.json"));
    }

    /** A session on {@code tee} with its settings in {@code configDir}, saying into {@code said}. */
    static PlaySession saying(World tee, Path configDir, List<String> said) {
        return new PlaySession(tee, null, List.of(), new PlayerFiles(new SettingsStore(configDir), s -> { }), said::add);
    }
}
