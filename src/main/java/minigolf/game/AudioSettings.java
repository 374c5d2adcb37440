package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import minigolf.io.AtomicFile;

/**
 * Volumes, 0 (off) to 1, kept in {@code <config>/audio.json} (its own file beside settings.json):
 * the master volume, the effects (putt, hits, splash, cup, applause) and the ambience.
 */
public record AudioSettings(double master, double effects, double ambience) {
    public static final AudioSettings DEFAULTS = new AudioSettings(0.8, 1.0, 0.35);

    public AudioSettings {
        for (double v : new double[]{master, effects, ambience}) {
            if (!(v >= 0 && v <= 1)) throw new IllegalArgumentException("volumes must be 0 to 1, got " + v);
        }
    }

    public static Path file(Path configDirectory) {
        return configDirectory.resolve("audio.json");
    }

    /** The stored volumes, the defaults when there is no file. */
    public static AudioSettings load(Path file) throws SaveGameException {
        if (!Files.exists(file)) return DEFAULTS;
        JsonFields f = new JsonFields(String.valueOf(file));
        JsonNode root = f.parse(JsonFields.readText(file, minigolf.course.Limits.SETTINGS_FILE_BYTES));
        f.onlyFields(root, null, List.of("master", "effects", "ambience"));
        double[] v = {DEFAULTS.master, DEFAULTS.effects, DEFAULTS.ambience};
        String[] names = {"master", "effects", "ambience"};
        for (int i = 0; i < 3; i++) {
            if (!root.has(names[i])) continue;
            v[i] = f.number(root, null, names[i]);
            if (!(v[i] >= 0 && v[i] <= 1)) throw f.error(names[i], "must be 0 to 1, got " + v[i]);
        }
        return new AudioSettings(v[0], v[1], v[2]);
    }

    public void save(Path file) throws SaveGameException {
        ObjectNode root = JsonFields.MAPPER.createObjectNode();
        root.put("master", master).put("effects", effects).put("ambience", ambience);
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            AtomicFile.write(file, (JsonFields.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n")
                    .getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new SaveGameException(String.valueOf(file), null, "cannot save: " + e.getMessage(), e);
        }
    }
}
