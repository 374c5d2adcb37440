package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import minigolf.course.Limits;
import minigolf.io.AtomicFile;
import minigolf.physics.Integrator;

/**
 * Reads and writes {@link UserSettings} as {@code settings.json} in the user's config folder:
 * the system property {@code minigolf.configDir} if set (tests), else {@code $XDG_CONFIG_HOME/minigolf},
 * else {@code ~/.config/minigolf}. Saved games go to its {@code saves} folder. A missing file means
 * the defaults; a broken one is reported in one line and the defaults are used.
 */
public final class SettingsStore {
    public static final String CONFIG_DIR_PROPERTY = "minigolf.configDir";
    private static final List<String> FIELDS = List.of("integrator", "dt", "vsync", "frameLimit", "fullscreen",
            "mouseSpeed", "strokeLimit", "heightColours", "playerNames", "noisePosition", "noiseVelocity",
            "hideFrictionFromBots", "aimGuide", "antiAliasing", "graphics", "windowWidth", "windowHeight", "practice", "classicFolder");

    private final Path directory;

    public SettingsStore(Path directory) {
        this.directory = directory;
    }

    /** The store in the user's config folder. */
    public static SettingsStore forUser() {
        return new SettingsStore(configDirectory(System.getProperty(CONFIG_DIR_PROPERTY), System.getenv(),
                System.getProperty("user.home")));
    }

    static Path configDirectory(String override, Map<String, String> env, String home) {
        if (override != null && !override.isBlank()) return Path.of(override);
        String xdg = env.get("XDG_CONFIG_HOME");
        // The XDG spec ignores relative paths.
        if (xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute()) return Path.of(xdg, "minigolf");
        return Path.of(home, ".config", "minigolf");
    }

    public Path directory() {
        return directory;
    }

    public Path file() {
        return directory.resolve("settings.json");
    }

    /** Where saved games go: {@code <config>/saves}. */
    public Path savesDirectory() {
        return directory.resolve("saves");
    }

    /** Removes the temporary files that a process killed while saving left in the config and saves folders. */
    public int removeStaleTemporaries() {
        return AtomicFile.removeStaleTemporaries(directory) + AtomicFile.removeStaleTemporaries(savesDirectory());
    }

    /**
     * The stored settings, or the defaults when there is no file yet. A file that cannot be used
     * throws a {@link SettingsException}: the file's own line and the same in a player's words.
     */
    public UserSettings load() throws SettingsException {
        if (!Files.exists(file())) return UserSettings.DEFAULTS;
        JsonNode[] root = new JsonNode[1];
        try {
            return read(root);
        } catch (SettingsException e) {
            throw e;
        } catch (SaveGameException e) {
            // The player's words name no file or folder, even where the system's reason would.
            String words = SettingWords.explain(e, root[0]).replace(file().toString(), "the file")
                    .replace(directory.toString(), "the settings folder");
            throw new SettingsException(e, words);
        }
    }

    /** Reads the file; {@code root[0]} is its parsed text once it parsed (for the player's words of an error). */
    private UserSettings read(JsonNode[] root) throws SaveGameException {
        String source = file().toString();
        JsonFields f = new JsonFields(source);
        root[0] = f.parse(JsonFields.readText(file(), Limits.SETTINGS_FILE_BYTES));
        return read(f, source, root[0]);
    }

    private UserSettings read(JsonFields f, String source, JsonNode root) throws SaveGameException {
        f.onlyFields(root, null, FIELDS);
        UserSettings d = UserSettings.DEFAULTS;
        try {
            Integrator integrator = root.has("integrator") ? Integrator.fromName(f.text(root, null, "integrator")) : d.integrator();
            if (integrator == null) throw f.error("integrator", "must be euler, rk2 or rk4");
            List<String> names = d.playerNames();
            if (root.has("playerNames")) {
                JsonNode a = f.array(root, null, "playerNames");
                names = new ArrayList<>();
                for (int i = 0; i < a.size(); i++) {
                    if (!a.get(i).isTextual()) throw f.error("playerNames[" + i + "]", "must be a string, got " + JsonFields.got(a.get(i)));
                    names.add(a.get(i).textValue());
                }
            }
            double dt = root.has("dt") ? f.number(root, null, "dt") : d.dt();
            if (minigolf.physics.SimulationSettings.dtProblem(dt) != null) {
                throw f.error("dt", minigolf.physics.SimulationSettings.dtProblem(dt));
            }
            return new UserSettings(integrator, dt,
                    root.has("vsync") ? f.bool(root, null, "vsync") : d.vsync(),
                    root.has("frameLimit") ? f.integer(root, null, "frameLimit", 0, 1000) : d.frameLimit(),
                    root.has("fullscreen") ? f.bool(root, null, "fullscreen") : d.fullscreen(),
                    root.has("mouseSpeed") ? f.number(root, null, "mouseSpeed") : d.mouseSpeed(),
                    root.has("strokeLimit") ? f.integer(root, null, "strokeLimit", 1, Game.MAX_STROKE_LIMIT) : d.strokeLimit(),
                    root.has("heightColours") ? f.bool(root, null, "heightColours") : d.heightColours(),
                    names,
                    root.has("noisePosition") ? f.number(root, null, "noisePosition") : d.noisePosition(),
                    root.has("noiseVelocity") ? f.number(root, null, "noiseVelocity") : d.noiseVelocity(),
                    root.has("hideFrictionFromBots") ? f.bool(root, null, "hideFrictionFromBots") : d.hideFrictionFromBots(),
                    root.has("aimGuide") ? f.bool(root, null, "aimGuide") : d.aimGuide(),
                    root.has("antiAliasing") ? f.bool(root, null, "antiAliasing") : d.antiAliasing(),
                    root.has("graphics") ? f.text(root, null, "graphics") : d.graphics(),
                    root.has("windowWidth") ? f.integer(root, null, "windowWidth", 0, 16384) : d.windowWidth(),
                    root.has("windowHeight") ? f.integer(root, null, "windowHeight", 0, 16384) : d.windowHeight(),
                    root.has("practice") ? f.bool(root, null, "practice") : d.practice(),
                    root.has("classicFolder") ? f.text(root, null, "classicFolder") : d.classicFolder());
        } catch (UserSettings.InvalidSetting e) {
            throw new SettingsException(new SaveGameException(source, null, e.getMessage(), e), e.forPlayer());
        }
    }

    /** The name a broken settings file is moved to before new settings are written, or null if it is not broken. */
    public Path keepBrokenFile() throws SaveGameException {
        if (!Files.exists(file(), java.nio.file.LinkOption.NOFOLLOW_LINKS)) return null;
        try {
            load();
            return null;
        } catch (SaveGameException broken) {
            for (int n = 1; n < 1000; n++) {
                Path kept = directory.resolve(n == 1 ? "settings.broken.json" : "settings.broken-" + n + ".json");
                if (Files.exists(kept, java.nio.file.LinkOption.NOFOLLOW_LINKS)) continue;
                try {
                    Files.move(file(), kept);
                    return kept;
                } catch (IOException e) {
                    throw new SaveGameException(file().toString(), null, "cannot save: the broken settings file"
                            + " cannot be moved aside to " + kept.getFileName() + ": " + e.getMessage(), e);
                }
            }
            throw new SaveGameException(file().toString(), null, "cannot save: too many settings.broken-N.json files");
        }
    }

    /** Loads the settings; a broken file gives the defaults and {@code problem[0]} its one-line message. */
    public UserSettings loadOrDefaults(String[] problem) {
        try {
            return load();
        } catch (SaveGameException e) {
            if (problem != null && problem.length > 0) problem[0] = e.getMessage();
            return UserSettings.DEFAULTS;
        }
    }

    /**
     * Writes the settings. A broken settings file is never overwritten: it is first renamed to
     * {@code settings.broken.json} (or {@code settings.broken-2.json}, ...), so nothing the user
     * wrote is lost.
     */
    public void save(UserSettings s) throws SaveGameException {
        keepBrokenFile();
        ObjectNode root = JsonFields.MAPPER.createObjectNode();
        root.put("integrator", s.integrator().cliName());
        root.put("dt", s.dt());
        root.put("vsync", s.vsync());
        root.put("frameLimit", s.frameLimit());
        root.put("fullscreen", s.fullscreen());
        root.put("mouseSpeed", s.mouseSpeed());
        root.put("strokeLimit", s.strokeLimit());
        root.put("heightColours", s.heightColours());
        root.put("aimGuide", s.aimGuide());
        root.put("antiAliasing", s.antiAliasing());
        root.put("graphics", s.graphics());
        root.put("windowWidth", s.windowWidth());
        root.put("windowHeight", s.windowHeight());
        root.put("practice", s.practice());
        if (!s.classicFolder().isEmpty()) root.put("classicFolder", s.classicFolder());
        ArrayNode names = root.putArray("playerNames");
        s.playerNames().forEach(names::add);
        root.put("noisePosition", s.noisePosition());
        root.put("noiseVelocity", s.noiseVelocity());
        root.put("hideFrictionFromBots", s.hideFrictionFromBots());
        try {
            Files.createDirectories(directory);
            String json = JsonFields.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(root) + "\n";
            AtomicFile.write(file(), json.getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new SaveGameException(file().toString(), null, "cannot save: " + e.getMessage(), e);
        }
    }
}
