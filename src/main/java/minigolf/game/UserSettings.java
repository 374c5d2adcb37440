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
        if (SimulationSettings.dtProblem(dt) != null) throw new IllegalArgumentException("dt " + SimulationSettings.dtProblem(dt));
        if (frameLimit < 0 || frameLimit > 1000) throw new IllegalArgumentException("frameLimit must be 0 to 1000, got " + frameLimit);
        if (!(mouseSpeed >= 0.1 && mouseSpeed <= 10)) throw new IllegalArgumentException("mouseSpeed must be 0.1 to 10, got " + mouseSpeed);
        if (strokeLimit < 1 || strokeLimit > Game.MAX_STROKE_LIMIT) {
            throw new IllegalArgumentException("strokeLimit must be 1 to " + Game.MAX_STROKE_LIMIT + ", got " + strokeLimit);
        }
        if (!(noisePosition >= 0 && noisePosition <= MAX_NOISE_POSITION)) {
            throw new IllegalArgumentException("noisePosition must be 0 to " + MAX_NOISE_POSITION + " m, got " + noisePosition);
        }
        if (!(noiseVelocity >= 0 && noiseVelocity <= MAX_NOISE_VELOCITY)) {
            throw new IllegalArgumentException("noiseVelocity must be 0 to " + MAX_NOISE_VELOCITY + " m/s, got " + noiseVelocity);
        }
        if (!GRAPHICS.contains(graphics)) throw new IllegalArgumentException("graphics must be auto, high or low, got " + graphics);
        boolean defaultSize = windowWidth == 0 && windowHeight == 0;
        if (!defaultSize && (windowWidth < 640 || windowWidth > 16384 || windowHeight < 480 || windowHeight > 16384)) {
            throw new IllegalArgumentException("the window size must be 0 x 0 (the default) or 640 to 16384 x 480 to 16384, got "
                    + windowWidth + " x " + windowHeight);
        }
        if (classicFolder == null) classicFolder = "";
        if (classicFolder.length() > MAX_FOLDER_LENGTH || classicFolder.indexOf('\0') >= 0) {
            throw new IllegalArgumentException("classicFolder must be a folder name of at most " + MAX_FOLDER_LENGTH + " characters");
        }
        playerNames = List.copyOf(playerNames);
        if (playerNames.isEmpty() || playerNames.size() > Game.MAX_PLAYERS) {
            throw new IllegalArgumentException("playerNames must hold 1 to " + Game.MAX_PLAYERS + " names");
        }
        for (String n : playerNames) {
            if (n == null || n.isBlank() || n.length() > Player.MAX_NAME_LENGTH) {
                throw new IllegalArgumentException("player names must be 1 to " + Player.MAX_NAME_LENGTH + " characters");
            }
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
