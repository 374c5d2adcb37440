package minigolf.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.function.BiConsumer;
import java.util.stream.Stream;
import minigolf.course.CourseException;
import minigolf.game.AimModel;
import minigolf.game.Loft;
import minigolf.game.BallReadout;
import minigolf.game.BotSeats;
import minigolf.game.BotCatalog;
import minigolf.game.BotConditions;
import minigolf.game.BotTurn;
import minigolf.game.CourseEdits;
import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.HighScores;
import minigolf.game.HoleReplay;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SavedRounds;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SettingsStore;
import minigolf.game.ShotPlanner;
import minigolf.game.ShotRecord;
import minigolf.game.StrokeAnimator;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import minigolf.render.AimView;
import minigolf.render.BallView;
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
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengl.GL11.*;

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
    private Path coursePath;
    Game game;
    /** The round being played (null for a single course); {@link #game} is its current hole's game. */
    RoundGame round;
    /** Scores kept between games (null when the file is broken: it is then left alone). */
    private HighScores highScores;
    private AudioSettings audio;
    /** Silent until the window is open, and where there is no audio device. */
    private Sounds sounds;
    /** Confetti and splashes (the renderer draws them; they end by themselves). */
    private final minigolf.render.Particles effects = new minigolf.render.Particles();
    /** The holed ball sinking into the cup (drawn until it is out of sight). */
    private final minigolf.render.CupDrop cupDrop = new minigolf.render.CupDrop();
    /** The round the next game plays (set by {@link #playRound} or the menu). */
    private Round roundToPlay;
    /** Frames the between-holes card has been shown (the headless run moves on by itself). */
    private int cardFrames;
    StrokeAnimator animator;
    private BotTurn botTurn;
    /** One bot per player per hole, so the planner's memory lasts across its strokes. */
    private final BotSeats botSeats = new BotSeats();
    private String message;
    private double messageUntil;
    private String notice;
    private final Deque<double[]> script;
    final Screens screens = new Screens(this);
    private final Thumbnails thumbnails = new Thumbnails();
    private List<CourseEntry> courses;
    private List<RoundEntry> rounds;

    Window window;
    SceneRenderer renderer;
    private RenderQuality quality = RenderQuality.HIGH;
    /** What the renderer probed as right for this machine (the "auto" graphics setting). */
    private RenderQuality autoQuality = RenderQuality.HIGH;
    OrbitCamera camera;
    NuklearLayer uiLayer;
    private boolean rebuildScene;
    /** Called at the start of every pass of the loop (drawn or not) with the window: tests drive resizes with it. */
    private BiConsumer<Integer, Window> loopHook = (pass, w) -> { };

    /** Keys and mouse: aiming, the loft, turning and moving the camera. */
    private final GameInput input = new GameInput(this);
    /** The aim guide's path for {@link #guideKey} (x, y, vx, vy), reused while the aim holds (AimView compares it by identity). */
    private float[] guidePath;
    /** An aim to show as soon as a human player can aim (play --aim, for screenshots), or null. */
    private double[] pendingAim;
    private double[] guideKey;
    private final Vector3f followTarget = new Vector3f();
    /** The time of the last frame drawn (for the camera's easing), NaN before the first. */
    private float lastDrawTime = Float.NaN;
    /** Set when a stroke ends: the camera turns towards the hole until it faces it or the player turns it. */
    boolean turnToHole;
    /** Watching a hole again ("Watch again", "Watch hole N"), and the screen to go back to. */
    private final ReplayPlayer replayer = new ReplayPlayer();
    private Screen replayReturn;

    public GameApp(World world, Options options) {
        this.options = options;
        this.store = options.store();
        String[] problem = new String[1];
        store.removeStaleTemporaries();
        this.settings = store.loadOrDefaults(problem);
        if (problem[0] != null) {
            // Shown until dismissed (a timed message would expire before the window exists) and on stderr.
            notice = "Settings ignored, the defaults are used: " + problem[0];
            System.err.println("minigolf: settings ignored, the defaults are used: " + problem[0]);
        }
        try {
            audio = AudioSettings.load(AudioSettings.file(store.directory()));
        } catch (SaveGameException e) {
            audio = AudioSettings.DEFAULTS;
            say("volumes ignored: " + e.getMessage());
        }
        try {
            highScores = HighScores.load(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            highScores = null;
            say("high scores ignored: " + e.getMessage());
        }
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
            try (NuklearLayer ui = new NuklearLayer(window.handle(), scale); Sounds sound = Sounds.open(audio)) {
                sounds = sound;
                uiLayer = ui;
                buildScene();
                try {
                    if (options.startPlayers() != null) {
                        if (roundToPlay != null) startRound(roundToPlay, options.startPlayers());
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
            drawFrame(fw, fh, (float) (now - start));
            frame++;
            boolean finalCard = screens.screen() == Screen.SCORECARD
                    || (screens.screen() == Screen.ROUND_CARD && round != null && round.isOver());
            overFrames = finalCard ? overFrames + 1 : 0;
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
                        recordScores(round.finishHole());
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

    private void say(String text) {
        message = text;
        messageUntil = (window != null ? glfwGetTime() : 0) + 5;
    }

    // ---- Drawing ------------------------------------------------------------------------------

    private void buildScene() {
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
        followTarget.set(camera.target());
        window.setTitle("Minigolf - " + world.course().name());
    }

    /**
     * Shows the aim (vx, vy) in m/s as if the player were dragging it, from the first frame a human
     * player can aim (until a mouse release or right click): for screenshots of the arrow and the aim guide.
     */
    public void showAim(double vx, double vy, int loftDegrees) {
        pendingAim = new double[]{vx, vy};
        input.loft = Loft.clamp(loftDegrees);
    }

    private void drawFrame(int fw, int fh, float time) {
        if (pendingAim != null && canAim()) {
            input.aiming = true;
            input.aimVelocity = pendingAim;
            pendingAim = null;
        }
        cupDrop.advanceTo(time);
        renderer.setBalls(ballViews());
        renderer.setAim(aimView());
        effects.advanceTo(time);
        renderer.setEffects(effects.mesh());
        followBall();
        camera.ease(Float.isNaN(lastDrawTime) ? 0 : time - lastDrawTime); // the clearance's moves glide
        lastDrawTime = time;
        renderer.render(camera, fw, fh, time);
        int mini = Math.min(fw, fh) / 4;
        renderer.renderMinimap(fw - mini - 12, 12, mini, fw, fh);
        if (screens.screen() == Screen.COURSES) thumbnails.renderNext(courses(), 200, 120);
        glViewport(0, 0, fw, fh);
        uiLayer.newFrame();
        screens.remember(this);
        screens.draw(this);
        uiLayer.render();
    }

    private List<BallView> ballViews() {
        List<BallView> views = new ArrayList<>();
        StrokeAnimator replayed = replayer.animator();
        if (screens.screen() == Screen.REPLAY && replayed != null) {
            double x = replayed.x(), y = replayed.y();
            float[] c = PlayerColors.of(replayer.shot().player());
            views.add(new BallView((float) x, (float) y, (float) Math.max(0, replayed.z()), c[0], c[1], c[2]));
            return views;
        }
        if (cupDrop.view() != null) views.add(cupDrop.view());
        if (game == null) {
            double x = world.course().start().x(), y = world.course().start().y();
            views.add(BallView.white(x, y, world.terrain().height(x, y)));
            return views;
        }
        int rolling = game.isShotInFlight() ? game.currentPlayer() : -1;
        for (int i = 0; i < game.players().size(); i++) {
            PlayerState s = game.player(i);
            if (s.status() == minigolf.game.PlayerStatus.HOLED && i != rolling) continue;
            boolean moving = i == rolling && animator != null;
            double x = moving ? animator.x() : s.x(), y = moving ? animator.y() : s.y();
            double z = moving ? animator.z() : world.terrain().height(x, y); // a chip's ball is drawn in the air
            float[] c = PlayerColors.of(i);
            views.add(new BallView((float) x, (float) y, (float) Math.max(0, z), c[0], c[1], c[2]));
        }
        return views;
    }

    private AimView aimView() {
        double[] aimVelocity = input.aimVelocity;
        if (!input.aiming || aimVelocity == null || game == null || game.currentPlayer() < 0) return null;
        double speed = Math.hypot(aimVelocity[0], aimVelocity[1]);
        if (speed < 1e-6) return null;
        PlayerState s = game.player(game.currentPlayer());
        double[] v = Loft.velocity(aimVelocity[0], aimVelocity[1], input.loft, world.physics().maxSpeed());
        return new AimView((float) s.x(), (float) s.y(), (float) world.terrain().height(s.x(), s.y()),
                (float) aimVelocity[0], (float) aimVelocity[1], (float) (speed / world.physics().maxSpeed()),
                settings.aimGuide() ? guidePath(s.x(), s.y(), v) : null);
    }

    /** The aim guide (AimGuide: the real engine, the game's settings; a chip's flight too), recomputed when the aim changes. */
    private float[] guidePath(double x, double y, double[] v) {
        double[] key = {x, y, v[0], v[1], v[2]};
        if (!java.util.Arrays.equals(key, guideKey)) {
            guidePath = minigolf.game.AimGuide.preview(game.world(), game.settings(), x, y, v[0], v[1], v[2], minigolf.game.AimGuide.SECONDS).points();
            guideKey = key;
        }
        return guidePath;
    }

    /** The camera glides after the ball in play: the rolling one, else the next player's. */
    private void followBall() {
        if (game == null || input.rotating || input.panning) return;
        StrokeAnimator replayed = replayer.animator();
        if (screens.screen() == Screen.REPLAY && replayed != null) {
            followTarget.set((float) replayed.x(), (float) replayed.y(), (float) world.terrain().height(replayed.x(), replayed.y()));
            camera.setTarget(camera.target().lerp(followTarget, 0.12f));
            return;
        }
        int seat = game.currentPlayer();
        if (seat < 0) return;
        double x = animator != null ? animator.x() : game.player(seat).x();
        double y = animator != null ? animator.y() : game.player(seat).y();
        followTarget.set((float) x, (float) y, (float) world.terrain().height(x, y));
        Vector3f t = camera.target();
        t.lerp(followTarget, 0.12f);
        camera.setTarget(t);
        if (turnToHole && animator == null) {
            // Once the balls are at rest, swing round behind the next ball, looking at the hole.
            double hx = world.hole().position().x() - x, hy = world.hole().position().y() - y;
            if (Math.hypot(hx, hy) < 1e-6) {
                turnToHole = false;
                return;
            }
            double want = Math.atan2(-hy, -hx), delta = Math.IEEEremainder(want - camera.yaw(), 2 * Math.PI);
            camera.rotate((float) (delta * 0.1), 0);
            if (Math.abs(delta) < 0.005) turnToHole = false;
        }
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
        return audio;
    }

    @Override
    public void applyVolumes(AudioSettings v) {
        audio = v;
        if (sounds != null) sounds.setVolumes(v);
        try {
            v.save(AudioSettings.file(store.directory()));
        } catch (SaveGameException e) {
            say("volumes not saved: " + e.getMessage());
        }
    }

    @Override
    public void startGame(List<Player> players) {
        if (roundToPlay != null) {
            startRound(roundToPlay, players);
            return;
        }
        round = null;
        cancelBot();
        animator = null;
        // The "realistic" noise, drawn from a new seed each game (saved with the game, so a resumed game goes on alike).
        game = new Game(world, settings.simulation(), players, settings.strokeLimit(), settings.noise(), System.nanoTime());
        camera.reset();
        screens.show(Screen.PLAYING);
        say(players.get(0).name() + " tees off. Drag back from the ball to aim; ESC pauses.");
    }

    private void startRound(Round r, List<Player> players) {
        cancelBot();
        botTurn = null;
        animator = null;
        round = new RoundGame(r, settings.simulation(), players, settings.strokeLimit(), settings.noise(), System.nanoTime());
        showHole();
        say(r.name() + ", hole 1 of " + r.size() + " (par " + r.hole(0).par() + "): " + players.get(0).name() + " tees off.");
    }

    /** Shows the round's current hole: its course, a fresh camera, the HUD. */
    private void showHole() {
        game = round.game();
        world = game.world();
        coursePath = null;
        buildScene();
        screens.show(Screen.PLAYING);
    }

    @Override
    public void nextHole() {
        if (round == null) return;
        if (round.isHoleOver()) recordScores(round.finishHole());
        if (!round.nextHole()) {
            screens.show(Screen.ROUND_CARD);
            return;
        }
        cancelBot();
        botTurn = null;
        animator = null;
        showHole();
        Round.Hole h = round.hole();
        say("Hole " + (round.holeIndex() + 1) + " of " + round.round().size() + ": " + world.course().name() + ", par " + h.par());
    }

    /** Personal bests for the hole just finished, and the table once the round is over; saved at once. */
    private void recordScores(int[] holeScores) {
        if (highScores == null) return;
        String name = round.round().name();
        List<HighScores.Achievement> news = new ArrayList<>(highScores.recordHole(name, round.holeIndex(), round.players(), holeScores));
        if (round.isOver()) {
            news.addAll(highScores.recordRound(name, round.scorecard(), round.players(), java.time.LocalDate.now()));
        }
        try {
            highScores.save(HighScores.file(store.directory()));
        } catch (SaveGameException e) {
            say("scores not saved: " + e.getMessage());
            return;
        }
        if (!news.isEmpty()) {
            say(String.join("; ", news.stream().map(a -> a.name() + ": " + a.what()).toList()));
        }
    }

    @Override
    public HighScores highScores() {
        return highScores;
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
        try {
            world = World.load(file);
            coursePath = file;
            roundToPlay = null;
            round = null;
            game = null;
            animator = null;
            rebuildScene = true;
            screens.show(Screen.MAIN_MENU);
            say("course: " + world.course().name());
        } catch (CourseException e) {
            say(e.getMessage());
        }
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
        if (game == null) return;
        try {
            Files.createDirectories(store.savesDirectory());
            Path file = store.savesDirectory().resolve((round != null ? "round-" : "game-")
                    + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")) + ".json");
            if (round != null) SavedRounds.save(round, file);
            else SavedGames.save(game, file);
            say("saved to " + file);
        } catch (IOException | SaveGameException e) {
            say("not saved: " + e.getMessage());
        }
    }

    @Override
    public void loadGame(Path file) {
        try {
            SavedRounds.AnySave save = SavedRounds.loadAny(file);
            if (save.round() != null) {
                RoundGame loaded = save.round();
                cancelBot();
                botTurn = null;
                round = loaded;
                roundToPlay = loaded.round();
                showHole();
                game = round.game();
                animator = game.isShotInFlight() ? new StrokeAnimator(game.activeStroke(), game.settings().dt()) : null;
                if (game.isOver()) screens.show(Screen.ROUND_CARD);
                say("loaded " + file.getFileName() + ": " + round.round().name() + ", hole " + (round.holeIndex() + 1));
                return;
            }
            SavedGames.Loaded loaded = save.game();
            cancelBot();
            botTurn = null;
            round = null;
            world = loaded.world();
            buildScene();
            game = loaded.resume();
            animator = game.isShotInFlight() ? new StrokeAnimator(game.activeStroke(), game.settings().dt()) : null;
            screens.show(game.isOver() ? Screen.SCORECARD : Screen.PLAYING);
            say("loaded " + file.getFileName());
        } catch (SaveGameException e) {
            say(e.getMessage());
        }
    }

    @Override
    public void applySettings(UserSettings newSettings, CourseEdits edits) {
        try {
            World edited = edits.applyTo(world);
            if (!edited.course().equals(world.course())) {
                world = edited;
                rebuildScene = true;
            }
        } catch (CourseException e) {
            throw new IllegalArgumentException(e.detail(), e);
        }
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
        try {
            store.save(settings);
        } catch (SaveGameException e) {
            say("settings not saved: " + e.getMessage());
        }
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
        cancelBot();
        botTurn = null;
        animator = null;
        game = null;
        round = null;
        screens.show(Screen.MAIN_MENU);
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
        Path dir = store.savesDirectory();
        if (!Files.isDirectory(dir)) return List.of();
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        } catch (IOException e) {
            return List.of();
        }
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
