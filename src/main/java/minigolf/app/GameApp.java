package minigolf.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.function.BiConsumer;
import minigolf.game.AimModel;
import minigolf.game.Loft;
import minigolf.game.BallReadout;
import minigolf.game.BotSeats;
import minigolf.game.BotConditions;
import minigolf.game.BotTurn;
import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.HighScores;
import minigolf.game.HoleReplay;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SettingsStore;
import minigolf.game.ShotPlanner;
import minigolf.game.ShotRecord;
import minigolf.game.StrokeAnimator;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import minigolf.render.OrbitCamera;
import minigolf.render.Png;
import minigolf.render.RenderQuality;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import minigolf.render.Window;
import minigolf.ui.NuklearLayer;
import minigolf.ui.PlayerColors;
import minigolf.ui.Screen;
import minigolf.ui.Screens;
import minigolf.ui.UiActions;
import minigolf.ui.UiView;
import org.joml.Vector3f;

import static org.lwjgl.glfw.GLFW.*;

/**
 * The game: one window, one render loop. Each frame polls input, advances the rolling ball at the
 * physics step (fixed, decoupled from the frame rate, drawn interpolated), runs bots on worker
 * threads, draws the course, the minimap and the interface screens. Everything GL happens on the
 * thread that calls {@link #run()}.
 */
public final class GameApp implements UiActions, UiView {
    /** How the game is started (the command line and tests fill it). */
    public record Options(Path coursePath, Path screenshot, int frames, List<Player> startPlayers,
                          List<double[]> scriptedShots, double timeScale, SettingsStore store, boolean visible,
                          boolean exitWhenOver) {
        public static Options interactive(Path coursePath) {
            return new Options(coursePath, null, 0, null, List.of(), 1, SettingsStore.forUser(), true, false);
        }
    }

    /** Frames a headless run (--frames) shows the card between holes before it plays the next. */
    static final int ROUND_CARD_FRAMES = 30;

    private final Options options;
    private final SettingsStore store;
    UserSettings settings;
    World world;
    Path coursePath;
    Game game;
    /** The round being played (null for a single course); {@link #game} is its current hole's game. */
    RoundGame round;
    /** Settings, volumes, high scores and saved games on disk. */
    final PlayerFiles files;
    /** Starting, moving on and ending games and rounds. */
    private final PlayFlow flow = new PlayFlow(this);
    /** Silent until the window is open, and where there is no audio device. */
    private Sounds sounds;
    /** Confetti and splashes (the renderer draws them; they end by themselves). */
    final minigolf.render.Particles effects = new minigolf.render.Particles();
    /** The holed ball sinking into the cup (drawn until it is out of sight). */
    final minigolf.render.CupDrop cupDrop = new minigolf.render.CupDrop();
    /** The round the next game plays (set by {@link #playRound} or the menu). */
    Round roundToPlay;
    /** Frames the between-holes card has been shown (the headless run moves on by itself). */
    private int cardFrames;
    StrokeAnimator animator;
    BotTurn botTurn;
    /** One bot per player per hole, so the planner's memory lasts across its strokes. */
    private final BotSeats botSeats = new BotSeats();
    private String message;
    private double messageUntil;
    private String notice;
    private final Deque<double[]> script;
    final Screens screens = new Screens(this);
    final Thumbnails thumbnails = new Thumbnails();
    private List<CourseEntry> courses;
    private List<RoundEntry> rounds;

    Window window;
    SceneRenderer renderer;
    private RenderQuality quality = RenderQuality.HIGH;
    /** What the renderer probed as right for this machine (the "auto" graphics setting). */
    private RenderQuality autoQuality = RenderQuality.HIGH;
    OrbitCamera camera;
    NuklearLayer uiLayer;
    boolean rebuildScene;
    /** Called at the start of every pass of the loop (drawn or not) with the window: tests drive resizes with it. */
    private BiConsumer<Integer, Window> loopHook = (pass, w) -> { };

    /** Keys and mouse: aiming, the loft, turning and moving the camera. */
    final GameInput input = new GameInput(this);
    /** What each frame shows: the balls, the aim and its guide, the camera following the ball. */
    private final GameView view = new GameView(this);
    /** Set when a stroke ends: the camera turns towards the hole until it faces it or the player turns it. */
    boolean turnToHole;
    /** Watching a hole again ("Watch again", "Watch hole N"), and the screen to go back to. */
    final ReplayPlayer replayer = new ReplayPlayer();
    private Screen replayReturn;

    public GameApp(World world, Options options) {
        this.options = options;
        this.store = options.store();
        this.files = new PlayerFiles(store, this::say);
        this.settings = files.loadedSettings();
        // Shown until dismissed (a timed message would expire before the window exists).
        if (files.settingsProblem() != null) notice = "Settings ignored, the defaults are used: " + files.settingsProblem();
        this.world = world;
        this.coursePath = options.coursePath();
        this.script = new ArrayDeque<>(options.scriptedShots());
    }

    /** Runs until the window closes or the requested frames are done; returns the game at the end (or null). */
    public Game run() {
        autoQuality = RenderQuality.probe(); // llvmpipe: no MSAA, smaller water targets (docs/rendering.md)
        quality = chosenQuality(settings);
        Window.Options wo = options.visible() ? new Window.Options(true, true, quality.samples(), true, 3, 3)
                : new Window.Options(true, false, 0, true, 3, 3);
        int ww = settings.windowWidth() > 0 ? settings.windowWidth() : 1280;
        int wh = settings.windowHeight() > 0 ? settings.windowHeight() : 720;
        try (Window w = new Window("Minigolf", ww, wh, wo)) {
            window = w;
            window.setVsync(settings.vsync() && options.frames() <= 0);
            // The player's full screen, not for scripted runs (tests and screenshots keep their window).
            if (settings.fullscreen() && options.visible() && options.frames() <= 0) window.toggleFullscreen();
            input.install();
            float scale = Math.max(1f, window.framebufferHeight() / 900f);
            try (NuklearLayer ui = new NuklearLayer(window.handle(), scale); Sounds sound = Sounds.open(files.volumes())) {
                sounds = sound;
                uiLayer = ui;
                buildScene();
                try {
                    if (options.startPlayers() != null) {
                        if (roundToPlay != null) flow.startRound(roundToPlay, options.startPlayers());
                        else startGame(options.startPlayers());
                    }
                    loop();
                } finally {
                    if (botTurn != null) botTurn.cancel();
                    thumbnails.close();
                    if (renderer != null) renderer.close();
                }
            }
        }
        return game;
    }

    /** Plays this round instead of a single course (before {@link #run()}: with the options' players it starts at once). */
    public void playRound(Round r) {
        roundToPlay = r;
    }

    /** Opens the help screen (what F1 does). */
    public void openHelp() {
        screens.openHelp();
    }

    /** The round being played, or null. */
    public RoundGame roundGame() {
        return round;
    }

    /** Sets what runs at the start of every pass of the render loop (for tests: resize, minimise, close). */
    public void onLoopPass(BiConsumer<Integer, Window> hook) {
        loopHook = hook;
    }

    private void loop() {
        double last = glfwGetTime(), start = last;
        int frame = 0, overFrames = 0, pass = 0;
        while (!window.shouldClose()) {
            loopHook.accept(pass++, window);
            if (window.shouldClose()) break;
            double now = glfwGetTime(), elapsed = Math.min(0.25, now - last);
            last = now;
            window.pollEvents();
            update(elapsed, now);
            int fw = window.framebufferWidth(), fh = window.framebufferHeight();
            if (fw <= 0 || fh <= 0 || window.isIconified()) {
                sleep(50); // minimised: keep the game going, draw nothing
                continue;
            }
            if (rebuildScene) buildScene();
            view.draw(fw, fh, (float) (now - start));
            frame++;
            overFrames = showsFinalCard() ? overFrames + 1 : 0;
            // A new window takes its content size in its second frame: stop once the scorecard has been drawn.
            boolean over = options.exitWhenOver() && overFrames >= 3;
            if ((options.frames() > 0 && frame >= options.frames()) || over) {
                if (options.screenshot() != null) Png.saveBackBuffer(options.screenshot(), fw, fh);
                window.swapBuffers();
                break;
            }
            window.swapBuffers();
            limitFrameRate(now);
        }
    }

    private void limitFrameRate(double frameStart) {
        if (options.frames() > 0 || (settings.vsync() && options.visible()) || settings.frameLimit() <= 0) return;
        double wait = frameStart + 1.0 / settings.frameLimit() - glfwGetTime();
        if (wait > 0.001) sleep((long) (wait * 1000));
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    // ---- Game logic per frame ---------------------------------------------------------------

    private void update(double elapsed, double now) {
        if (message != null && now > messageUntil) message = null;
        Screen screen = screens.screen();
        if (screen == Screen.REPLAY) {
            updateReplay(elapsed);
            return;
        }
        if (screen == Screen.ROUND_CARD && round != null && !round.isOver() && options.frames() > 0
                && ++cardFrames >= ROUND_CARD_FRAMES) {
            nextHole(); // a headless run moves on by itself; a player presses "Next hole"
            return;
        }
        boolean running = screen == Screen.PLAYING || screen == Screen.TEST_BOT;
        if (game == null || !running) return;
        if (animator != null) {
            animator.advance(elapsed, options.timeScale());
            if (animator.isFinished()) {
                ShotRecord r = game.completeShot();
                animator = null;
                turnToHole = true;
                Player p = game.players().get(r.player());
                say(p.name() + ": " + describe(r));
                if (game.isOver()) {
                    if (round != null) {
                        files.recordScores(round, round.finishHole());
                        cardFrames = 0;
                        screens.show(Screen.ROUND_CARD);
                    } else {
                        screens.show(Screen.SCORECARD);
                    }
                    return;
                }
            }
        }
        if (game.isShotInFlight() || game.isOver()) return;
        int seat = game.currentPlayer();
        Player p = game.players().get(seat);
        if (p.isBot()) {
            if (botTurn == null) {
                ShotPlanner planner = botSeats.planner(seat, p.bot(), game.world());
                if (planner == null) {
                    say("no bot named " + p.bot() + "; " + p.name() + " cannot play");
                    return;
                }
                PlayerState s = game.player(seat);
                botTurn = new BotTurn(planner, game.world(), game.settings(), s.x(), s.y(), s.total(),
                        31L * game.history().size() + seat,
                        BotConditions.of(game, seat, settings.hideFrictionFromBots()));
            } else if (botTurn.isDone()) {
                BotTurn done = botTurn;
                botTurn = null;
                if (done.shot() != null) {
                    hit(done.shot()[0], done.shot()[1], done.shot()[2]);
                } else {
                    say(p.name() + ": " + done.failure());
                    if ("cancelled".equals(done.failure())) toMainMenu();
                }
            }
        } else if (!script.isEmpty()) {
            double[] v = script.poll();
            hit(v[0], v[1], v.length > 2 ? v[2] : 0);
        }
    }

    private void updateReplay(double elapsed) {
        switch (replayer.advance(elapsed, options.timeScale(), game.settings().dt(), () -> strokeSounds(false))) {
            case STROKE_STARTED -> {
                ShotRecord r = replayer.shot();
                StrokeFeedback.hit(sounds, Math.sqrt(r.vx() * r.vx() + r.vy() * r.vy() + r.vz() * r.vz()),
                        world.physics().maxSpeed());
            }
            case OVER -> {
                int mismatches = replayer.counts()[1];
                stopReplay();
                say(mismatches == 0 ? "replay over: every stroke ended exactly where it did in play"
                        : mismatches + " replayed strokes ended elsewhere than in play");
            }
            case ROLLING -> {
            }
        }
    }

    @Override
    public void watchReplay() {
        if (game == null || game.history().isEmpty() || game.isShotInFlight() || screens.screen() == Screen.REPLAY) return;
        startReplay(HoleReplay.of(game));
    }

    @Override
    public void watchHole(int hole) {
        if (round == null || hole < 0 || hole >= round.holesFinished() || round.holeStrokes(hole).isEmpty()
                || game.isShotInFlight() || screens.screen() == Screen.REPLAY) return;
        World holeWorld = round.round().hole(hole).world();
        if (holeWorld != world) { // another hole's course on screen while it is watched
            world = holeWorld;
            rebuildScene = true;
        }
        startReplay(new HoleReplay(holeWorld, game.settings(), round.holeStrokes(hole)));
    }

    private void startReplay(HoleReplay r) {
        cancelBot();
        botTurn = null;
        replayer.start(r);
        replayReturn = screens.screen();
        screens.show(Screen.REPLAY);
    }

    @Override
    public void stopReplay() {
        if (screens.screen() != Screen.REPLAY) return;
        replayer.stop();
        if (game != null && world != game.world()) { // back to the hole being played
            world = game.world();
            rebuildScene = true;
        }
        screens.show(replayReturn);
    }

    /** Strokes replayed by the last "Watch again" and how many ended elsewhere than in play (for tests). */
    public int[] replayCounts() {
        return replayer.counts();
    }

    @Override
    public String replayCaption() {
        return replayer.caption(game.players());
    }

    private static String describe(ShotRecord r) {
        return switch (r.outcome()) {
            case HOLED -> "in the hole!";
            case STOPPED -> String.format(Locale.ROOT, "stopped at (%.2f, %.2f)", r.endX(), r.endY());
            case WATER -> "in the water: one penalty stroke, back to where the stroke began";
            case OUT -> "out of bounds: one penalty stroke, back to where the stroke began";
            case TIMEOUT -> "still rolling after the time limit; it stays where it is";
        };
    }

    void say(String text) {
        message = text;
        messageUntil = (window != null ? glfwGetTime() : 0) + 5;
    }

    // ---- Drawing ------------------------------------------------------------------------------

    void buildScene() {
        rebuildScene = false;
        effects.clear(); // a new hole: the last one's confetti stays behind
        cupDrop.clear();
        if (renderer != null) renderer.close();
        renderer = null;
        renderer = new SceneRenderer(world.course(), world.terrain(),
                settings.heightColours() ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN, quality);
        if (coursePath != null) renderer.setCourseFolder(coursePath.toAbsolutePath().getParent());
        renderer.setAntiAliasing(settings.antiAliasing() && quality.samples() == 0); // FXAA only without MSAA
        int fw = Math.max(1, window.framebufferWidth()), fh = Math.max(1, window.framebufferHeight());
        camera = OrbitCamera.behindBall(world.course(), world.terrain(), (float) fw / fh);
        camera.setClearance(minigolf.render.CameraClearance.of(world.course(), world.terrain()::height));
        view.sceneBuilt();
        window.setTitle("Minigolf - " + world.course().name());
    }

    /**
     * Shows the aim (vx, vy) in m/s as if the player were dragging it, from the first frame a human
     * player can aim (until a mouse release or right click): for screenshots of the arrow and the aim guide.
     */
    public void showAim(double vx, double vy, int loftDegrees) {
        view.showAim(vx, vy);
        input.loft = Loft.clamp(loftDegrees);
    }

    /** The game or the round is over and its card is shown. */
    boolean showsFinalCard() {
        return screens.screen() == Screen.SCORECARD
                || (screens.screen() == Screen.ROUND_CARD && round != null && round.isOver());
    }

    boolean canAim() {
        return screens.screen() == Screen.PLAYING && game != null && !game.isShotInFlight() && !game.isOver()
                && !game.players().get(game.currentPlayer()).isBot();
    }

    // ---- UiActions ----------------------------------------------------------------------------

    private minigolf.physics.TrajectoryListener strokeSounds(boolean firstStroke) {
        return StrokeFeedback.listener(sounds, firstStroke, effects, world);
    }

    /** A played stroke's sounds and effects, and the ball in the player's colour dropping into the cup. */
    private minigolf.physics.TrajectoryListener strokeFeedback(boolean firstStroke, int seat) {
        return StrokeFeedback.listener(sounds, firstStroke, effects, world, cupDrop, PlayerColors.of(seat));
    }

    @Override
    public AudioSettings volumes() {
        return files.volumes();
    }

    @Override
    public void applyVolumes(AudioSettings v) {
        if (sounds != null) sounds.setVolumes(v);
        files.saveVolumes(v);
    }

    @Override
    public void startGame(List<Player> players) {
        flow.startGame(players);
    }



    @Override
    public void nextHole() {
        flow.nextHole();
    }

    @Override
    public HighScores highScores() {
        return files.highScores();
    }

    @Override
    public void chooseRound(Round r) {
        roundToPlay = r;
        screens.show(Screen.NEW_GAME);
    }

    @Override
    public void hit(double vx, double vy, double vz) {
        if (game == null || game.isShotInFlight() || game.isOver()) return;
        String problem = AimModel.checkTyped(vx, vy, vz, world.physics().maxSpeed());
        if (problem != null) {
            say(problem);
            return;
        }
        boolean firstStroke = game.player(game.currentPlayer()).total() == 0;
        animator = new StrokeAnimator(game.startShot(vx, vy, vz, strokeFeedback(firstStroke, game.currentPlayer())),
                game.settings().dt());
        StrokeFeedback.hit(sounds, Math.sqrt(vx * vx + vy * vy + vz * vz), world.physics().maxSpeed());
        input.loft = 0; // the next stroke starts as a putt again
    }

    @Override
    public void selectCourse(Path file) {
        flow.selectCourse(file);
    }

    @Override
    public void testBot(String bot) {
        startGame(List.of(Player.bot(bot, bot)));
        screens.show(Screen.TEST_BOT);
        say("watching " + bot + " play; ESC stops");
    }

    @Override
    public void cancelBot() {
        if (botTurn != null) botTurn.cancel();
        // A cancelled worker may still be ending: its bot must not be asked again.
        botSeats.clear();
    }

    @Override
    public void saveGame() {
        if (game != null) files.save(game, round);
    }

    @Override
    public void loadGame(Path file) {
        flow.load(file);
    }

    @Override
    public void applySettings(UserSettings newSettings) {
        UserSettings old = settings;
        settings = newSettings;
        window.setVsync(settings.vsync() && options.frames() <= 0);
        if (settings.fullscreen() != window.isFullscreen()) window.toggleFullscreen();
        if (!window.isFullscreen() && settings.windowWidth() > 0
                && (settings.windowWidth() != old.windowWidth() || settings.windowHeight() != old.windowHeight())) {
            glfwSetWindowSize(window.handle(), settings.windowWidth(), settings.windowHeight());
        }
        if (!settings.graphics().equals(old.graphics())) {
            quality = chosenQuality(settings); // multisampling stays as the window was made (next start)
            rebuildScene = true;
        }
        if (renderer != null) renderer.setAntiAliasing(settings.antiAliasing() && quality.samples() == 0);
        files.saveSettings(settings);
    }

    /** The renderer's quality now (for tests). */
    public RenderQuality renderQuality() {
        return quality;
    }

    /** The renderer's quality for the player's graphics setting: auto is what the probe found. */
    private RenderQuality chosenQuality(UserSettings s) {
        return switch (s.graphics()) {
            case "high" -> RenderQuality.HIGH;
            case "low" -> RenderQuality.SOFTWARE;
            default -> autoQuality;
        };
    }

    @Override
    public void toMainMenu() {
        flow.toMainMenu();
    }

    @Override
    public void createCourse() {
        try {
            minigolf.editor.ui.ProcessLauncher.start("edit");
            say("the editor opens in its own window");
        } catch (IOException e) {
            say("cannot open the editor: " + e.getMessage());
        }
    }

    @Override
    public void quit() {
        window.requestClose();
    }

    // ---- UiView -------------------------------------------------------------------------------

    @Override
    public World world() {
        return world;
    }

    @Override
    public Game game() {
        return game;
    }

    @Override
    public RoundGame round() {
        return round;
    }

    @Override
    public Round chosenRound() {
        return roundToPlay;
    }

    @Override
    public List<RoundEntry> rounds() {
        if (rounds == null) rounds = CourseFolders.rounds(store);
        return rounds;
    }

    /** Exposed for tests: the screen shown now. */
    public Screen screen() {
        return screens.screen();
    }

    /** Opens a screen as its button would (for tests and screenshots; call on the render thread, e.g. from a loop hook). */
    public void showScreen(Screen s) {
        screens.open(s, this);
    }

    @Override
    public BallReadout readout() {
        if (game == null || game.currentPlayer() < 0) return null;
        if (animator != null) {
            return BallReadout.of(world, animator.x(), animator.y(), animator.vx(), animator.vy(), animator.ax(), animator.ay());
        }
        PlayerState s = game.player(game.currentPlayer());
        return BallReadout.of(world, s.x(), s.y(), 0, 0, 0, 0);
    }

    @Override
    public BotTurn botTurn() {
        return botTurn;
    }

    @Override
    public float[] toScreen(double x, double y) {
        if (camera == null || world == null) return null;
        // A little above the ground, so the line is not hidden in the grass.
        float z = (float) (world.terrain().height(x, y) + 0.03);
        float[] p = camera.project(new Vector3f((float) x, (float) y, z), window.framebufferWidth(), window.framebufferHeight());
        return uiLayer == null ? p : uiLayer.toInterface(p, window.framebufferWidth());
    }

    @Override
    public UserSettings settings() {
        return settings;
    }

    @Override
    public void refreshCourses() {
        courses = null;
        rounds = null;
    }

    @Override
    public List<CourseEntry> courses() {
        if (courses == null) courses = CourseFolders.list(store);
        return courses;
    }

    @Override
    public List<Path> savedGames() {
        return files.savedGames();
    }

    @Override
    public String notice() {
        return notice;
    }

    @Override
    public void dismissNotice() {
        notice = null;
    }

    @Override
    public String message() {
        return message;
    }

    @Override
    public double aimSpeed() {
        return input.aiming && input.aimVelocity != null ? Math.hypot(input.aimVelocity[0], input.aimVelocity[1]) : -1;
    }

    @Override
    public int loftDegrees() {
        return input.loft;
    }

    @Override
    public int thumbnail(CourseEntry course) {
        return thumbnails.texture(course.file());
    }
}
