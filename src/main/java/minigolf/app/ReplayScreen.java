package minigolf.app;

import java.util.ArrayList;
import java.util.List;
import minigolf.game.HoleReplay;
import minigolf.game.ShotRecord;
import minigolf.game.StrokeAnimator;
import minigolf.physics.World;
import minigolf.render.BallView;
import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiWindowFlags;
import minigolf.ui.PlayerColors;
import minigolf.ui.Screen;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * Watching a hole again ("Watch again", "Watch hole N"): its course on screen, its strokes played
 * one after another from where each was hit, the camera after the ball; at the end (or Stop, ESC)
 * back to the screen it was opened from.
 */
final class ReplayScreen extends GameScreen {
    private final ReplayPlayer replayer = new ReplayPlayer();
    private World world;
    private Screen back;

    ReplayScreen(GameApp app) {
        super(app);
    }

    /** Starts watching {@code r}; {@code returnTo} is shown when it ends. */
    void start(HoleReplay r, Screen returnTo) {
        app.play().cancelBot();
        replayer.start(r);
        world = r.world();
        back = returnTo;
        app.setScreen(this);
    }

    /** Strokes replayed and how many ended elsewhere than in play. */
    int[] counts() {
        return replayer.counts();
    }

    @Override
    World course() {
        return world;
    }

    /** The bricks as the replay has reached: rebuilt stroke by stroke, as play left them. */
    @Override
    minigolf.physics.CourseState courseState() {
        return replayer.courseNow();
    }

    @Override
    public void update(double elapsed) {
        double dt = app.play().game().settings().dt();
        switch (replayer.advance(elapsed, app.timeScale(), dt,
                () -> StrokeFeedback.listener(app.sounds(), false, app.scene().effects(), world))) {
            case STROKE_STARTED -> {
                ShotRecord r = replayer.shot();
                StrokeFeedback.hit(app.sounds(), Math.sqrt(r.vx() * r.vx() + r.vy() * r.vy() + r.vz() * r.vz()),
                        world.physics().maxSpeed());
            }
            case OVER -> {
                int mismatches = replayer.counts()[1];
                stop();
                app.say(mismatches == 0 ? "replay over: every stroke ended exactly where it did in play"
                        : mismatches + " replayed strokes ended elsewhere than in play");
            }
            case ROLLING -> {
            }
        }
    }

    void stop() {
        replayer.stop();
        app.setScreen(back);
    }

    @Override
    public void render(float w, float h) {
        String caption = replayer.caption(app.play().game().players());
        Gui.setNextWindowPos(w * 0.5f, 12, GuiCond.Always, 0.5f, 0f);
        Gui.begin("##replay", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
        Gui.alignTextToFramePadding();
        Gui.textColored(1f, 0.85f, 0.3f, 1f, caption == null ? "Replay" : caption);
        Gui.sameLine();
        if (Gui.button("Stop")) stop();
        Gui.end();
    }

    @Override
    double clock() {
        StrokeAnimator a = replayer.animator();
        return a == null ? replayer.lastClock() : a.clock();
    }

    @Override
    List<BallView> balls() {
        List<BallView> views = new ArrayList<>();
        StrokeAnimator a = replayer.animator();
        if (a == null) return views;
        float[] c = PlayerColors.of(replayer.shot().player());
        views.add(new BallView((float) a.x(), (float) a.y(), (float) Math.max(0, a.z()), c[0], c[1], c[2]));
        return views;
    }

    @Override
    BallView rolling() {
        List<BallView> b = balls();
        return b.isEmpty() ? null : b.get(0);
    }

    @Override
    BallView marker() {
        return null;
    }

    @Override
    void directCamera(CourseScene scene, float dt, float aspect) {
        StrokeAnimator a = replayer.animator();
        if (a != null) scene.follow(a.x(), a.y(), false, dt);
        else scene.hold();
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        stop();
        return true;
    }
}
