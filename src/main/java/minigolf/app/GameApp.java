package minigolf.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.BiConsumer;
import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.HoleReplay;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SettingsStore;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import minigolf.render.RenderQuality;
import minigolf.render.Window;
import minigolf.render.WindowApp;
import minigolf.render.WindowLoop;
import minigolf.ui.NuklearLayer;
import minigolf.ui.PlayerColors;
import minigolf.ui.Screen;
import minigolf.ui.ScreenHost;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.glViewport;

/**
 * The game window, in the manner of libGDX's {@code Game}: it owns the services every screen uses
 * (what is being played, the 3D course behind the screens, the player's files, sound, messages)
 * and shows one {@link GameScreen} at a time; input goes to the screen shown first, then to the
 * camera and the keys that work everywhere (F1, F11, R, H). The window loop is {@link WindowLoop},
 * shared with the editor. Everything GL happens on the thread that calls {@link #run()}.
 */
public final class GameApp implements WindowApp {
    /** How the game is started (the command line and tests fill it). */
    public record Options(Path coursePath, Path screenshot, int frames, List<Player> startPlayers,
                          List<double[]> scriptedShots, double timeScale, SettingsStore store, boolean visible,
                          boolean exitWhenOver) {
        public static Options interactive(Path coursePath) {
            return new Options(coursePath, null, 0, null, List.of(), 1, SettingsStore.forUser(), true, false);
        }
    }

    /** The game's screens, each made once: a form keeps what was typed into it. */
    public record Screens(MainMenuScreen mainMenu, CourseSelectScreen courseSelect, NewGameScreen newGame,
                          PlayingScreen playing, TestBotScreen testBot, PauseScreen pause, SettingsScreen settings,
                          ScorecardScreen scorecard, RoundCardScreen roundCard, ReplayScreen replay, HelpScreen help,
                          OnlineScreen online, LobbyScreen lobby) {
        List<Screen> all() {
            return List.of(mainMenu, courseSelect, newGame, playing, testBot, pause, settings, scorecard, roundCard, replay, help,
                    online, lobby);
        }
    }

    private final Options options;
    private final PlayerFiles files;
    private UserSettings settings;
    private final Toasts toasts = new Toasts(this::clock);
    private final PlaySession play;
    private final CourseScene scene = new CourseScene();
    private final CameraControls cameraControls = new CameraControls(this);
    private final Thumbnails thumbnails = new Thumbnails();
    private final Hud hud = new Hud(this);
    private final Screens screens;
    private final ScreenHost host;
    private Window window;
    private NuklearLayer uiLayer;
    /** Silent until the window is open, and where there is no audio device. */
    private Sounds sounds;
    private java.util.function.BooleanSupplier finishWhen = () -> false;
    /** Frames in a row that showed a final card (a scripted run stops after a few). */
    private int finalCardFrames;
    private BiConsumer<Integer, Window> loopHook = (pass, w) -> { };
    /** An online room to enter as soon as the window is open (the command line), or null. */
    private OnlinePlay.Entry onlineStart;
    private java.util.function.Consumer<String> roomCodeListener = code -> { };

    public GameApp(World world, Options options) {
        this.options = options;
        this.files = new PlayerFiles(options.store(), this::say);
        this.settings = files.loadedSettings();
        // Shown until dismissed (a timed message would expire before the window exists).
        if (files.settingsProblem() != null) {
            toasts.setNotice(settingsNotice(files.settingsProblem()));
        }
        this.play = new PlaySession(world, options.coursePath(), options.scriptedShots(), files, this::say);
        this.screens = new Screens(new MainMenuScreen(this), new CourseSelectScreen(this), new NewGameScreen(this),
                new PlayingScreen(this), new TestBotScreen(this), new PauseScreen(this), new SettingsScreen(this),
                new ScorecardScreen(this), new RoundCardScreen(this), new ReplayScreen(this), new HelpScreen(this),
                new OnlineScreen(this), new LobbyScreen(this));
        this.host = new ScreenHost(screens.mainMenu());
    }

    /** Runs until the window closes or the requested frames are done; returns the game at the end (or null). */
    public Game run() {
        scene.probeQuality(settings);
        RenderQuality quality = scene.quality();
        Window.Options wo = options.visible() ? new Window.Options(true, true, quality.samples(), true, 3, 3)
                : new Window.Options(true, false, 0, true, 3, 3);
        int ww = settings.windowWidth() > 0 ? settings.windowWidth() : 1280;
        int wh = settings.windowHeight() > 0 ? settings.windowHeight() : 720;
        try (Window w = new Window("Minigolf", ww, wh, wo)) {
            window = w;
            window.setVsync(settings.vsync() && options.frames() <= 0);
            // The player's full screen, not for scripted runs (tests and screenshots keep their window).
            if (settings.fullscreen() && options.visible() && options.frames() <= 0) window.toggleFullscreen();
            installInput();
            float scale = Math.max(1f, window.framebufferHeight() / 900f);
            try (NuklearLayer ui = new NuklearLayer(window.handle(), scale); Sounds sound = Sounds.open(files.volumes())) {
                sounds = sound;
                uiLayer = ui;
                play.setFeedback(new PlaySession.Feedback() {
                    @Override
                    public minigolf.physics.TrajectoryListener stroke(World world, boolean firstStroke, int seat) {
                        return StrokeFeedback.listener(sounds, firstStroke, scene.effects(), world, scene.cupDrop(),
                                PlayerColors.of(seat));
                    }

                    @Override
                    public void hit(double speed, double maxSpeed) {
                        StrokeFeedback.hit(sounds, speed, maxSpeed);
                    }
                });
                try {
                    if (options.startPlayers() != null) startGame(options.startPlayers());
                    if (onlineStart != null) startOnline(onlineStart);
                    new WindowLoop(window, this).screenshot(options.screenshot()).onPass(loopHook).run();
                } finally {
                    play.cancelBot();
                    thumbnails.close();
                    scene.close();
                    for (Screen s : screens.all()) s.dispose();
                }
            }
        }
        return play.game();
    }

    // ---- The window loop ---------------------------------------------------------------------

    @Override
    public void update(double elapsed, double now) {
        current().update(elapsed);
    }

    @Override
    public void render(int fw, int fh, float time) {
        host.resize(fw, fh);
        GameScreen s = current();
        scene.show(s.course(), s.course() == play.world() ? play.coursePath() : null, settings, fw, fh);
        scene.showBricks(s.courseState());
        // Each world's quiet background loop (setAmbience does nothing when it already plays).
        if (sounds != null) sounds.setAmbience(minigolf.theme.Themes.of(s.course().course().world()).ambience());
        s.directCamera(scene, scene.sinceLastFrame(time), (float) fw / Math.max(1, fh));
        scene.setClock(s.clock());
        scene.draw(fw, fh, time, s.balls(), s.aim(), s.marker(), s.rolling());
        glViewport(0, 0, fw, fh);
        uiLayer.newFrame();
        float w = uiLayer.displayWidth(), h = uiLayer.displayHeight();
        current().render(w, h); // the screen may have changed during update
        toasts.render(w, h);
        uiLayer.render();
        finalCardFrames = current().showsFinalCard() ? finalCardFrames + 1 : 0;
    }

    @Override
    public boolean finished(int framesDrawn) {
        // A new window takes its content size in its second frame: stop once the final card has been drawn.
        return (options.frames() > 0 && framesDrawn >= options.frames()) || (options.exitWhenOver() && finalCardFrames >= 3)
                || finishWhen.getAsBoolean();
    }

    /**
     * Ends the run after the first frame drawn while {@code condition} holds (checked after the frame,
     * so the frame shows that moment; the screenshot, if any, is of it): pictures of a moment such as
     * a computer opponent thinking.
     */
    public void finishWhen(java.util.function.BooleanSupplier condition) {
        finishWhen = condition;
    }

    @Override
    public double minFrameSeconds() {
        if (options.frames() > 0 || (settings.vsync() && options.visible()) || settings.frameLimit() <= 0) return 0;
        return 1.0 / settings.frameLimit();
    }

    private void installInput() {
        long h = window.handle();
        glfwSetKeyCallback(h, (win, key, scancode, action, mods) -> {
            if (action != GLFW_PRESS || (uiLayer != null && uiLayer.wantsKeyboard())) return;
            if (current().keyPressed(key, mods)) return;
            switch (key) {
                case GLFW_KEY_F1 -> openHelp();
                case GLFW_KEY_F11 -> window.toggleFullscreen();
                case GLFW_KEY_R -> scene.resetCamera();
                case GLFW_KEY_H -> {
                    if (scene.renderer() != null) {
                        scene.renderer().terrainPass().setColorMode(scene.renderer().terrainPass().colorMode().next());
                    }
                }
                default -> {
                }
            }
        });
        glfwSetMouseButtonCallback(h, (win, button, action, mods) -> {
            boolean down = action == GLFW_PRESS;
            double[] x = new double[1], y = new double[1];
            glfwGetCursorPos(win, x, y);
            if (down && uiLayer != null && uiLayer.wantsMouse()) return;
            boolean used = current().mouseButton(button, down, mods, x[0], y[0]);
            cameraControls.mouseButton(button, down, mods, x[0], y[0], used);
        });
        glfwSetCursorPosCallback(h, (win, x, y) -> {
            int[] ww = new int[1], wh = new int[1];
            glfwGetWindowSize(win, ww, wh);
            cameraControls.cursorMoved(x, y, current().cursorMoved(x, y), wh[0]);
        });
        glfwSetScrollCallback(h, (win, xoff, yoff) -> {
            if (uiLayer != null && uiLayer.wantsMouse()) return;
            if (!current().scrolled(yoff)) cameraControls.zoom(yoff);
        });
    }

    // ---- Services the screens use --------------------------------------------------------------

    PlaySession play() {
        return play;
    }

    CourseScene scene() {
        return scene;
    }

    PlayerFiles files() {
        return files;
    }

    Thumbnails thumbnails() {
        return thumbnails;
    }

    Window window() {
        return window;
    }

    Hud hud() {
        return hud;
    }

    /** A course point (x, y) on the terrain in interface pixels, or null when off screen (the bot's plan). */
    float[] toScreen(double x, double y) {
        World world = scene.world();
        if (world == null) return null;
        // A little above the ground, so the line is not hidden in the grass.
        return toScreen(x, y, world.terrain().height(x, y) + 0.03);
    }

    /** A point (x, y, z) of the course in interface pixels, or null when off screen or before the first frame. */
    float[] toScreen(double x, double y, double z) {
        if (scene.camera() == null) return null;
        float[] p = scene.camera().project(new org.joml.Vector3f((float) x, (float) y, (float) z), window.framebufferWidth(),
                window.framebufferHeight());
        return uiLayer == null ? p : uiLayer.toInterface(p, window.framebufferWidth());
    }

    /** Window coordinates (the cursor's) to framebuffer pixels. */
    double[] toFramebuffer(double x, double y) {
        int[] ww = new int[1], wh = new int[1];
        glfwGetWindowSize(window.handle(), ww, wh);
        double sx = (double) window.framebufferWidth() / Math.max(1, ww[0]);
        double sy = (double) window.framebufferHeight() / Math.max(1, wh[0]);
        return new double[]{x * sx, y * sy};
    }

    NuklearLayer uiLayer() {
        return uiLayer;
    }

    Sounds sounds() {
        return sounds;
    }

    /** Strokes scripted runs play per second of animation, per real second. */
    double timeScale() {
        return options.timeScale();
    }

    /** A scripted run (--frames): nobody is there to press "Next hole". */
    boolean scripted() {
        return options.frames() > 0;
    }

    void say(String text) {
        toasts.say(text);
    }

    /** GLFW's clock once the window is open, else 0. */
    private double clock() {
        return window != null ? glfwGetTime() : 0;
    }

    public UserSettings settings() {
        return settings;
    }

    public Screens screens() {
        return screens;
    }

    /** The screen shown now. */
    public Screen screen() {
        return host.current();
    }

    private GameScreen current() {
        return (GameScreen) host.current();
    }

    /** Shows {@code s}; call on the render thread (a screen's button, or a test's loop hook). */
    public void setScreen(Screen s) {
        host.setScreen(s);
    }

    // ---- Where the screens lead ----------------------------------------------------------------

    /** A game on the chosen course, or the chosen round, for these players. */
    public void startGame(List<Player> players) {
        play.start(players, settings);
        scene.resetCamera();
        setScreen(screens.playing());
    }

    /** Enters a room on a game server (its lobby, then play); the seat is remembered for a resume. */
    void startOnline(OnlinePlay.Entry entry) {
        java.nio.file.Path memoryFile = OnlineMemory.file(files.store().directory());
        play.startOnline(new OnlinePlay(entry, this::say, (room, token) -> {
            // The server and name the seat was taken with (the command line's may differ from the screen's last).
            OnlineMemory.seat(entry, room, token).save(memoryFile);
            roomCodeListener.accept(room);
        }));
        setScreen(screens.lobby());
    }

    /** Play ends; the main menu. */
    public void toMainMenu() {
        play.end();
        setScreen(screens.mainMenu());
    }

    /** The Settings screen, going back to the screen shown now. */
    public void openSettings() {
        screens.settings().open(host.current());
        setScreen(screens.settings());
    }

    /** The help screen (F1), going back to the screen shown now; F1 again closes it. */
    public void openHelp() {
        if (host.current() == screens.help()) {
            screens.help().close();
            return;
        }
        screens.help().open(host.current());
        setScreen(screens.help());
    }

    /** Plays the current hole's strokes again, exactly as played. */
    public void watchReplay() {
        Game game = play.game();
        if (game == null || game.history().isEmpty() || game.isShotInFlight() || host.current() == screens.replay()) return;
        screens.replay().start(HoleReplay.of(game), host.current());
    }

    /** Plays finished hole {@code hole} (0-based) of the round again, exactly as played (also after a load). */
    public void watchHole(int hole) {
        RoundGame round = play.round();
        if (round == null || hole < 0 || hole >= round.holesFinished() || round.holeStrokes(hole).isEmpty()
                || play.game().isShotInFlight() || host.current() == screens.replay()) return;
        screens.replay().start(new HoleReplay(round.round().hole(hole).world(), play.game().settings(), round.holeStrokes(hole)),
                host.current());
    }

    /** Applies and keeps the player's settings: window size, full screen and graphics at once. */
    public void applySettings(UserSettings newSettings) {
        UserSettings old = settings;
        settings = newSettings;
        if (window != null) { // before the window opens (tests), only the settings change
            window.setVsync(settings.vsync() && options.frames() <= 0);
            if (settings.fullscreen() != window.isFullscreen()) window.toggleFullscreen();
            if (!window.isFullscreen() && settings.windowWidth() > 0
                    && (settings.windowWidth() != old.windowWidth() || settings.windowHeight() != old.windowHeight())) {
                glfwSetWindowSize(window.handle(), settings.windowWidth(), settings.windowHeight());
            }
        }
        scene.applySettings(old, settings);
        files.saveSettings(settings);
    }

    /** Keeps the names typed in New game (in the settings file), to be offered the next time. */
    void rememberPlayerNames(List<String> names) {
        if (names.equals(settings.playerNames())) return;
        try {
            settings = settings.withPlayerNames(names);
        } catch (IllegalArgumentException e) {
            return; // a name the settings cannot keep (the game itself refused it already)
        }
        files.saveSettings(settings);
    }

    void applyVolumes(AudioSettings v) {
        if (sounds != null) sounds.setVolumes(v);
        files.saveVolumes(v);
    }

    /** Opens the course editor in its own window. */
    void createCourse() {
        try {
            minigolf.editor.ui.ProcessLauncher.start("edit");
            say("the editor opens in its own window");
        } catch (IOException e) {
            say("cannot open the editor: " + e.getMessage());
        }
    }

    void quit() {
        window.requestClose();
    }

    // ---- For the command line and tests ---------------------------------------------------------

    /** Plays this round instead of a single course (before {@link #run()}: with the options' players it starts at once). */
    public void playRound(Round r) {
        play.chooseRound(r);
    }

    /**
     * Shows the aim (vx, vy) in m/s as if the player were dragging it, from the first frame a human
     * player can aim (until a mouse release or right click): for screenshots of the arrow and the aim guide.
     */
    public void showAim(double vx, double vy, int loftDegrees) {
        screens.playing().showAim(vx, vy, loftDegrees);
    }

    /**
     * Enters an online room as soon as the window opens (before {@link #run()}); {@code roomCode}
     * hears the room's code when the seat is taken (the command line prints it).
     */
    public void playOnline(java.net.URI server, String name, String create, int seats, List<String> bots, String room,
                           java.util.function.Consumer<String> roomCode) {
        onlineStart = new OnlinePlay.Entry(server, name, create, seats, bots, true, room, null);
        roomCodeListener = roomCode;
    }

    /** Sets what runs at the start of every pass of the render loop (for tests: resize, minimise, close). */
    public void onLoopPass(BiConsumer<Integer, Window> hook) {
        loopHook = hook;
    }

    /** The game being played, or null. */
    public Game game() {
        return play.game();
    }

    /** The round being played, or null. */
    public RoundGame roundGame() {
        return play.round();
    }

    /** The course of the game being played or chosen (not a replayed hole's). */
    public World world() {
        return play.world();
    }

    /** The course drawn now (a replayed hole's while it is watched). */
    public World shownWorld() {
        return scene.world();
    }

    /** The renderer's quality now (for tests). */
    public RenderQuality renderQuality() {
        return scene.quality();
    }

    /**
     * The notice for a settings file that was not used: what is wrong in a player's words, what the
     * game plays with instead, and that nothing of the file is lost (SettingsStore keeps it aside).
     */
    static String settingsNotice(String problem) {
        return "Your settings file was not used.\n" + problem
                + "\nEvery setting is at its default for now.\nYour file is kept: it is renamed settings.broken.json"
                + " when new settings are saved.";
    }

    public String notice() {
        return toasts.notice();
    }

    /** Where the notice at the top ends (0 when none is shown): a panel at the top goes below it. */
    float noticeBottom() {
        return toasts.noticeBottom();
    }

    Toasts toasts() {
        return toasts;
    }

    public void dismissNotice() {
        toasts.dismissNotice();
    }

    public void saveGame() {
        play.save();
    }

    public void loadGame(Path file) {
        if (!play.load(file)) return;
        Game g = play.game();
        if (play.round() != null) setScreen(g.isOver() ? screens.roundCard() : screens.playing());
        else setScreen(g.isOver() ? screens.scorecard() : screens.playing());
    }

    public List<Path> savedGames() {
        return files.savedGames();
    }

    /** Strokes replayed by the last "Watch again" and how many ended elsewhere than in play (for tests). */
    public int[] replayCounts() {
        return screens.replay().counts();
    }
}
