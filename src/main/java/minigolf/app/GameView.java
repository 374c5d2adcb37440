package minigolf.app;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.game.AimGuide;
import minigolf.game.Loft;
import minigolf.game.PlayerState;
import minigolf.game.PlayerStatus;
import minigolf.game.StrokeAnimator;
import minigolf.physics.World;
import minigolf.render.AimView;
import minigolf.render.BallView;
import minigolf.ui.PlayerColors;
import minigolf.ui.Screen;
import org.joml.Vector3f;

import static org.lwjgl.opengl.GL11.glViewport;

/**
 * What one frame of the game shows, built from the game's state: the balls (the rolling one where
 * the animation has it, a replayed one, the one dropping into the cup), the aim arrow and its guide,
 * the camera gliding after the ball in play, then the minimap and the interface on top.
 */
final class GameView {
    private final GameApp app;
    private final Vector3f followTarget = new Vector3f();
    /** The aim guide's path for {@link #guideKey} (x, y, vx, vy, vz), reused while the aim holds (AimView compares it by identity). */
    private float[] guidePath;
    private double[] guideKey;
    /** An aim to show as soon as a human player can aim (play --aim, for screenshots), or null. */
    private double[] pendingAim;
    /** The time of the last frame drawn (for the camera's easing), NaN before the first. */
    private float lastDrawTime = Float.NaN;
    /** The final card's view has been set up (it turns from there), and the clearance it set aside. */
    private boolean onCard;
    private minigolf.render.CameraClearance cardClearance;
    /** The picture shifts the card's view replaced (x, y). */
    private float[] cardShift;

    GameView(GameApp app) {
        this.app = app;
    }

    /** A new scene: the camera's follow point starts where the camera looks. */
    void sceneBuilt() {
        followTarget.set(app.camera.target());
        onCard = false; // a new camera, with its own clearance
        cardClearance = null;
    }

    /** Shows the aim (vx, vy) m/s from the first frame a human player can aim (for screenshots). */
    void showAim(double vx, double vy) {
        pendingAim = new double[]{vx, vy};
    }

    void draw(int fw, int fh, float time) {
        GameInput input = app.input;
        if (pendingAim != null && app.canAim()) {
            input.aiming = true;
            input.aimVelocity = pendingAim;
            pendingAim = null;
        }
        app.cupDrop.advanceTo(time);
        app.renderer.setBalls(ballViews());
        app.renderer.setAim(aimView());
        app.effects.advanceTo(time);
        app.renderer.setEffects(app.effects.mesh());
        float dt = Float.isNaN(lastDrawTime) ? 0 : time - lastDrawTime;
        if (app.showsFinalCard()) {
            cardView(dt);
        } else {
            if (onCard) { // back to following a ball
                app.camera.setClearance(cardClearance);
                app.camera.setScreenShiftX(cardShift[0]);
                app.camera.setScreenShiftY(cardShift[1]);
            }
            onCard = false;
            followBall();
        }
        app.camera.ease(dt); // the clearance's moves glide
        lastDrawTime = time;
        app.renderer.render(app.camera, fw, fh, time);
        int mini = Math.min(fw, fh) / 4;
        app.renderer.renderMinimap(fw - mini - 12, 12, mini, fw, fh);
        if (app.screens.screen() == Screen.COURSES) app.thumbnails.renderNext(app.courses(), 200, 120);
        glViewport(0, 0, fw, fh);
        app.uiLayer.newFrame();
        app.screens.remember(app);
        app.screens.draw(app);
        app.uiLayer.render();
    }

    private List<BallView> ballViews() {
        List<BallView> views = new ArrayList<>();
        World world = app.world;
        StrokeAnimator replayed = app.replayer.animator();
        if (app.screens.screen() == Screen.REPLAY && replayed != null) {
            float[] c = PlayerColors.of(app.replayer.shot().player());
            views.add(new BallView((float) replayed.x(), (float) replayed.y(), (float) Math.max(0, replayed.z()), c[0], c[1], c[2]));
            return views;
        }
        if (app.cupDrop.view() != null) views.add(app.cupDrop.view());
        if (app.game == null) {
            double x = world.course().start().x(), y = world.course().start().y();
            views.add(BallView.white(x, y, world.terrain().height(x, y)));
            return views;
        }
        StrokeAnimator animator = app.animator;
        int rolling = app.game.isShotInFlight() ? app.game.currentPlayer() : -1;
        for (int i = 0; i < app.game.players().size(); i++) {
            PlayerState s = app.game.player(i);
            if (s.status() == PlayerStatus.HOLED && i != rolling) continue;
            boolean moving = i == rolling && animator != null;
            double x = moving ? animator.x() : s.x(), y = moving ? animator.y() : s.y();
            double z = moving ? animator.z() : world.terrain().height(x, y); // a chip's ball is drawn in the air
            float[] c = PlayerColors.of(i);
            views.add(new BallView((float) x, (float) y, (float) Math.max(0, z), c[0], c[1], c[2]));
        }
        return views;
    }

    private AimView aimView() {
        GameInput input = app.input;
        double[] aimVelocity = input.aimVelocity;
        if (!input.aiming || aimVelocity == null || app.game == null || app.game.currentPlayer() < 0) return null;
        World world = app.world;
        double speed = Math.hypot(aimVelocity[0], aimVelocity[1]);
        if (speed < 1e-6) return null;
        PlayerState s = app.game.player(app.game.currentPlayer());
        double[] v = Loft.velocity(aimVelocity[0], aimVelocity[1], input.loft, world.physics().maxSpeed());
        return new AimView((float) s.x(), (float) s.y(), (float) world.terrain().height(s.x(), s.y()),
                (float) aimVelocity[0], (float) aimVelocity[1], (float) (speed / world.physics().maxSpeed()),
                app.settings.aimGuide() ? guidePath(s.x(), s.y(), v) : null);
    }

    /** The aim guide (AimGuide: the real engine, the game's settings; a chip's flight too), recomputed when the aim changes. */
    private float[] guidePath(double x, double y, double[] v) {
        double[] key = {x, y, v[0], v[1], v[2]};
        if (!Arrays.equals(key, guideKey)) {
            guidePath = AimGuide.preview(app.game.world(), app.game.settings(), x, y, v[0], v[1], v[2], AimGuide.SECONDS).points();
            guideKey = key;
        }
        return guidePath;
    }

    /**
     * Behind the final card the camera leaves the last ball (a view that a tree beside it could tip
     * steeply down onto the green) for the whole course: with the card it cuts to the course's
     * middle at {@link #CARD_PITCH} and a distance that frames the course from every side, then turns slowly round
     * it. "Play again" or "Watch hole" brings the ball-following camera back.
     */
    private void cardView(float dt) {
        if (app.input.rotating || app.input.panning) return;
        if (!onCard) {
            World world = app.world;
            minigolf.course.Bounds b = world.course().bounds();
            double cx = 0.5 * (b.minX() + b.maxX()), cy = 0.5 * (b.minY() + b.maxY());
            app.camera.setTarget(new Vector3f((float) cx, (float) cy, (float) Math.max(0, world.terrain().height(cx, cy))));
            app.camera.rotate(0, CARD_PITCH - app.camera.pitch());
            cardShift = new float[]{app.camera.screenShiftX(), app.camera.screenShiftY()};
            app.camera.setScreenShiftX(CARD_SHIFT_X);
            app.camera.setScreenShiftY(0);
            app.camera.frameFromAllSides(world.course(), world.terrain(),
                    (float) app.window.framebufferWidth() / Math.max(1, app.window.framebufferHeight()), 0.92f);
            // The overview looks at the whole course, not at a ball a tree could hide: from that far the
            // clearance would only pull the eye into the crowns round the middle.
            cardClearance = app.camera.clearance();
            app.camera.setClearance(null);
            onCard = true;
        }
        app.camera.rotate(CARD_TURN * dt, 0);
    }

    /**
     * The final card's view: its pitch, its turn (radians per second), and the course's middle
     * right of the screen's, clear of the card at the left ({@code Screens.leftOfCourse}).
     */
    static final float CARD_PITCH = (float) Math.toRadians(40), CARD_TURN = 0.08f, CARD_SHIFT_X = 0.42f;

    /** The camera glides after the ball in play: the rolling one, else the next player's. */
    private void followBall() {
        if (app.game == null || app.input.rotating || app.input.panning) return;
        World world = app.world;
        StrokeAnimator replayed = app.replayer.animator();
        if (app.screens.screen() == Screen.REPLAY && replayed != null) {
            followTarget.set((float) replayed.x(), (float) replayed.y(), (float) world.terrain().height(replayed.x(), replayed.y()));
            app.camera.setTarget(app.camera.target().lerp(followTarget, 0.12f));
            return;
        }
        int seat = app.game.currentPlayer();
        if (seat < 0) return;
        StrokeAnimator animator = app.animator;
        double x = animator != null ? animator.x() : app.game.player(seat).x();
        double y = animator != null ? animator.y() : app.game.player(seat).y();
        followTarget.set((float) x, (float) y, (float) world.terrain().height(x, y));
        Vector3f t = app.camera.target();
        t.lerp(followTarget, 0.12f);
        app.camera.setTarget(t);
        if (app.turnToHole && animator == null) {
            // Once the balls are at rest, swing round behind the next ball, looking at the hole.
            double hx = world.hole().position().x() - x, hy = world.hole().position().y() - y;
            if (Math.hypot(hx, hy) < 1e-6) {
                app.turnToHole = false;
                return;
            }
            double want = Math.atan2(-hy, -hx), delta = Math.IEEEremainder(want - app.camera.yaw(), 2 * Math.PI);
            app.camera.rotate((float) (delta * 0.1), 0);
            if (Math.abs(delta) < 0.005) app.turnToHole = false;
        }
    }
}
