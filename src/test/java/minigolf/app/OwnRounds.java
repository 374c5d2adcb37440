package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;

/** A player's own round in a config folder (tests): {@code holes} times the first tee, par 2 each. */
final class OwnRounds {
    private OwnRounds() {
    }

    static void write(Path config, String file, String name, int holes) throws IOException {
        Files.createDirectories(config.resolve("rounds"));
        Path tee = config.resolve("holes/tee.json");
        if (!Files.exists(tee)) {
            Files.createDirectories(tee.getParent());
            Files.copy(Path.of(System.getProperty("minigolf.projectDir", "."), "courses/holes/01-first-tee.json"), tee);
        }
        String hole = "{\"course\": \"../holes/tee.json\", \"par\": 2}";
        Files.writeString(config.resolve("rounds").resolve(file), "{\"format\": 1, \"name\": \"" + name + "\", \"holes\": ["
                + String.join(", ", Collections.nCopies(holes, hole)) + "]}");
    }
}
