package minigolf.game;

import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.physics.Integrator;
import minigolf.physics.SimulationSettings;

/**
 * The player's preferences, kept in the user's config folder ({@link SettingsStore}): how strokes
 * are integrated, the window, the controls and the players of the last game.
 *
 * @param frameLimit  frames per second when vsync is off or has no effect (0 = unlimited)
 * @param mouseSpeed  camera rotation per pixel of drag, as a factor of the default
 * @param playerNames the names offered in the new-game dialog (1 to 4)
 * @param noisePosition the "realistic" setting: standard deviation in m of each stroke's start, per axis
 *                      (0 to {@value #MAX_NOISE_POSITION}), for every player, human or bot
 * @param noiseVelocity the "realistic" setting: standard deviation in m/s of the velocity played, per
 *                      component (0 to {@value #MAX_NOISE_VELOCITY})
 * @param hideFrictionFromBots bot players see every friction value as a prior and learn the truth
 *                      from their own strokes (minigolf.bot.friction)
 * @param aimGuide      while aiming, show where the ball would go in its first second (for
 *                      beginners; off is the "pro" setting)
 * @param antiAliasing  smooth edges with FXAA where the window has no MSAA (software rendering,
 *                      where it costs about 8 ms a frame at 1280x720; off by default)
 * @param graphics      graphics quality: {@code auto} (high on a real GPU, low on a software
 *                      rasteriser), {@code high} or {@code low} (docs/rendering.md, RenderQuality)
 * @param windowWidth   the window's size when not full screen, pixels; 0 and 0: 1280 x 720
 * @param windowHeight  (both 0, or 640 to 16384 wide and 480 to 16384 high)
 * @param practice      practice (expert) mode: the Shot panel for typed velocities and the ball's
 *                      physics readout in the HUD (off by default; V switches it in the game)
 * @param classicFolder where the course select's "Classic tracks" are read from (what
 *                      {@code minigolf import-tracks} wrote); empty: {@code <config>/classic}
 */
public record UserSettings(Integrator integrator, double dt, boolean vsync, int frameLimit, boolean fullscreen,
                           double mouseSpeed, int strokeLimit, boolean heightColours, List<String> playerNames,
                           double noisePosition, double noiseVelocity, boolean hideFrictionFromBots,
                           boolean aimGuide, boolean antiAliasing, String graphics, int windowWidth,
                           int windowHeight, boolean practice, String classicFolder) {
    /** The graphics qualities a player can choose (before DEFAULTS, which checks against it). */
    public static final List<String> GRAPHICS = List.of("auto", "high", "low");
    public static final UserSettings DEFAULTS = new UserSettings(Integrator.RK4, SimulationSettings.DEFAULT_DT, true, 60,
            false, 1.0, Game.DEFAULT_STROKE_LIMIT, false, List.of("Player 1", "Player 2", "Player 3", "Player 4"), 0, 0,
            false, true, false, "auto", 0, 0, false, "");
    public static final double MIN_DT = SimulationSettings.MIN_DT, MAX_DT = SimulationSettings.MAX_DT;
    /** The longest classic-tracks folder name kept. */
    public static final int MAX_FOLDER_LENGTH = 4096;
    /** Beyond these a putt is a lottery, not "realistic". */
    public static final double MAX_NOISE_POSITION = 0.5, MAX_NOISE_VELOCITY = 1;
    /** What the Settings screen's "Realistic" box turns on: a club golfer's spread (docs/bots.md, "Noise"). */
    public static final double REALISTIC_POSITION = 0.01, REALISTIC_VELOCITY = 0.05;

    /** Settings without noise. */
    public UserSettings(Integrator integrator, double dt, boolean vsync, int frameLimit, boolean fullscreen,
                        double mouseSpeed, int strokeLimit, boolean heightColours, List<String> playerNames) {
        this(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours, playerNames, 0, 0,
                false, true, false, "auto", 0, 0, false, "");
    }

    public UserSettings {
        if (integrator == null) throw new IllegalArgumentException("integrator must be given");
        if (SimulationSettings.dtProblem(dt) != null) throw new InvalidSetting("dt", "dt " + SimulationSettings.dtProblem(dt), dt);
        if (frameLimit < 0 || frameLimit > 1000) throw new InvalidSetting("frameLimit", "frameLimit must be 0 to 1000, got " + frameLimit, frameLimit);
        if (!(mouseSpeed >= 0.1 && mouseSpeed <= 10)) throw new InvalidSetting("mouseSpeed", "mouseSpeed must be 0.1 to 10, got " + mouseSpeed, mouseSpeed);
        if (strokeLimit < 1 || strokeLimit > Game.MAX_STROKE_LIMIT) {
            throw new InvalidSetting("strokeLimit", "strokeLimit must be 1 to " + Game.MAX_STROKE_LIMIT + ", got " + strokeLimit, strokeLimit);
        }
        if (!(noisePosition >= 0 && noisePosition <= MAX_NOISE_POSITION)) {
            throw new InvalidSetting("noisePosition", "noisePosition must be 0 to " + MAX_NOISE_POSITION + " m, got " + noisePosition,
                    noisePosition);
        }
        if (!(noiseVelocity >= 0 && noiseVelocity <= MAX_NOISE_VELOCITY)) {
            throw new InvalidSetting("noiseVelocity", "noiseVelocity must be 0 to " + MAX_NOISE_VELOCITY + " m/s, got " + noiseVelocity,
                    noiseVelocity);
        }
        if (!GRAPHICS.contains(graphics)) {
            throw new InvalidSetting("graphics", "graphics must be auto, high or low, got " + graphics,
                    graphics == null ? "empty" : JsonFields.shown(graphics));
        }
        boolean defaultSize = windowWidth == 0 && windowHeight == 0;
        if (!defaultSize && (windowWidth < 640 || windowWidth > 16384 || windowHeight < 480 || windowHeight > 16384)) {
            throw new InvalidSetting("windowWidth", "the window size must be 0 x 0 (the default) or 640 to 16384 x 480 to 16384, got "
                    + windowWidth + " x " + windowHeight, windowWidth + " x " + windowHeight + " pixels");
        }
        if (classicFolder == null) classicFolder = "";
        if (classicFolder.length() > MAX_FOLDER_LENGTH || classicFolder.indexOf('\0') >= 0) {
            throw new InvalidSetting("classicFolder", "classicFolder must be a folder name of at most " + MAX_FOLDER_LENGTH + " characters",
                    classicFolder.indexOf('\0') >= 0 ? "a name with a zero character" : "a name of " + classicFolder.length() + " characters");
        }
        playerNames = List.copyOf(playerNames);
        if (playerNames.isEmpty() || playerNames.size() > Game.MAX_PLAYERS) {
            throw new InvalidSetting("playerNames", "playerNames must hold 1 to " + Game.MAX_PLAYERS + " names",
                    playerNames.isEmpty() ? "empty" : playerNames.size() + " names");
        }
        for (String n : playerNames) {
            if (n == null || n.isBlank() || n.length() > Player.MAX_NAME_LENGTH) {
                throw new InvalidSetting("playerNames", "player names must be 1 to " + Player.MAX_NAME_LENGTH + " characters",
                        n == null || n.isBlank() ? "a list with an empty name" : "a list with a name of " + n.length() + " characters");
            }
        }
    }

    /**
     * A setting out of its range: the message for the terminal and the command line (the field's
     * name, the value as given), and {@link #forPlayer()} in a player's words.
     */
    public static final class InvalidSetting extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;
        private final String field;
        private final String shownValue;

        InvalidSetting(String field, String message, double value) {
            this(field, message, SettingWords.shown(field, value));
        }

        InvalidSetting(String field, String message, String shownValue) {
            super(message);
            this.field = field;
            this.shownValue = shownValue;
        }

        /** The settings file's field ({@code windowWidth} for the window size). */
        public String field() {
            return field;
        }

        /** "The stroke limit is 0; it must be a whole number from 1 to 99 strokes a hole." */
        public String forPlayer() {
            return SettingWords.sentence(field, shownValue);
        }
    }

    /** The noise a new game plays every stroke with. */
    public NoiseModel noise() {
        return new NoiseModel(noisePosition, noiseVelocity);
    }

    /** The "realistic" setting: both noises at once (0 turns it off). */
    public UserSettings withNoise(double position, double velocity) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, position, velocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public SimulationSettings simulation() {
        return new SimulationSettings(integrator, dt, SimulationSettings.DEFAULT_MAX_TIME);
    }

    public UserSettings withIntegrator(Integrator v) {
        return new UserSettings(v, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withDt(double v) {
        return new UserSettings(integrator, v, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide,
                antiAliasing, graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withVsync(boolean v) {
        return new UserSettings(integrator, dt, v, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide,
                antiAliasing, graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withFrameLimit(int v) {
        return new UserSettings(integrator, dt, vsync, v, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withFullscreen(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, v, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withMouseSpeed(double v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, v, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withStrokeLimit(int v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, v, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withHeightColours(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, v,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withPlayerNames(List<String> v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, v, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withHideFrictionFromBots(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, noisePosition, noiseVelocity, v, aimGuide, antiAliasing,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withAimGuide(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, v,
                antiAliasing, graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withAntiAliasing(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit,
                heightColours, playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, v,
                graphics, windowWidth, windowHeight, practice, classicFolder);
    }

    public UserSettings withGraphics(String v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing, v, windowWidth,
                windowHeight, practice, classicFolder);
    }

    public UserSettings withWindowSize(int width, int height) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing, graphics, width,
                height, practice, classicFolder);
    }

    public UserSettings withPractice(boolean v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing, graphics, windowWidth,
                windowHeight, v, classicFolder);
    }

    public UserSettings withClassicFolder(String v) {
        return new UserSettings(integrator, dt, vsync, frameLimit, fullscreen, mouseSpeed, strokeLimit, heightColours,
                playerNames, noisePosition, noiseVelocity, hideFrictionFromBots, aimGuide, antiAliasing, graphics,
                windowWidth, windowHeight, practice, v);
    }
}
