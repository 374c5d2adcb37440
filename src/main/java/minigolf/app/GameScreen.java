package minigolf.app;

import java.util.ArrayList;
import java.util.List;
import minigolf.game.Game;
import minigolf.game.PlayerState;
import minigolf.game.PlayerStatus;
import minigolf.game.StrokeAnimator;
import minigolf.physics.World;
import minigolf.render.AimView;
import minigolf.render.BallView;
import minigolf.ui.PlayerColors;
import minigolf.ui.Screen;

/**
 * A screen of the game window: besides its interface it says what the 3D view behind it shows
 * (which course, which balls, an aim) and what the camera does. By default that is the course in
 * play, every ball on it, and the camera following the ball in play.
 */
abstract class GameScreen implements Screen {
    protected final GameApp app;

    GameScreen(GameApp app) {
        this.app = app;
    }

    /** The course drawn behind the screen. */
    World course() {
        return app.play().world();
    }

    /** The balls drawn: the rolling one where its animation has it, the others at rest, the one dropping into the cup. */
    List<BallView> balls() {
        List<BallView> views = new ArrayList<>();
        CourseScene scene = app.scene();
        if (scene.cupDrop().view() != null) views.add(scene.cupDrop().view());
        World world = course();
        Game game = app.play().game();
        if (game == null) {
            double x = world.course().start().x(), y = world.course().start().y();
            views.add(BallView.white(x, y, world.terrain().height(x, y)));
            return views;
        }
        StrokeAnimator animator = app.play().animator();
        int rolling = app.play().rollingSeat();
        for (int i = 0; i < game.players().size(); i++) {
            PlayerState s = game.player(i);
            if (s.status() == PlayerStatus.HOLED && i != rolling) continue;
            boolean moving = i == rolling && animator != null;
            double x = moving ? animator.x() : s.x(), y = moving ? animator.y() : s.y();
            double z = moving ? animator.z() : world.terrain().height(x, y); // a chip's ball is drawn in the air
            float[] c = PlayerColors.of(i);
            views.add(new BallView((float) x, (float) y, (float) Math.max(0, z), c[0], c[1], c[2]));
        }
        return views;
    }

    /** The aim drawn (arrow and guide), or null. */
    AimView aim() {
        return null;
    }

    /** Moves the camera for this frame ({@code dt} seconds since the last): after the ball in play. */
    void directCamera(CourseScene scene, float dt, float aspect) {
        Game game = app.play().game();
        if (game == null || game.currentPlayer() < 0) {
            scene.hold();
            return;
        }
        StrokeAnimator animator = app.play().animator();
        PlayerState s = game.player(game.currentPlayer());
        scene.follow(animator != null ? animator.x() : s.x(), animator != null ? animator.y() : s.y(), animator == null);
    }

    /** A final card is shown (the game or the round is over): a scripted run that waits for it may end. */
    boolean showsFinalCard() {
        return false;
    }
}
