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

    /** The bricks standing on the course drawn (null: as the course starts): the game's, as its strokes left them. */
    minigolf.physics.CourseState courseState() {
        Game game = app.play().game();
        return game != null && course() == app.play().world() ? game.courseState() : null;
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
        // The current player's ball last, so that it is drawn over any ball at the same spot.
        int current = game.currentPlayer();
        for (int i = 0; i < game.players().size(); i++) {
            if (i != current) addBall(views, game, i);
        }
        if (current >= 0) addBall(views, game, current);
        return views;
    }

    /** The course clock the 3D view shows (moving obstacles): PlaySession.viewClock. */
    double clock() {
        return app.play().viewClock();
    }

    /** Seat {@code seat}'s ball where it is (the rolling one where its animation has it); none once holed. */
    private void addBall(List<BallView> views, Game game, int seat) {
        BallView b = ball(game, seat);
        if (b != null) views.add(b);
    }

    /** Seat {@code seat}'s ball as drawn, or null when it is in the cup. */
    BallView ball(Game game, int seat) {
        StrokeAnimator animator = app.play().animator();
        // Online, the server's stroke is animated on the game as it was before it (no shot in flight there).
        boolean moving = app.play().rollingSeat() == seat && animator != null;
        PlayerState s = game.player(seat);
        if (s.status() == PlayerStatus.HOLED && !moving) return null;
        World world = course();
        double x = moving ? animator.x() : s.x(), y = moving ? animator.y() : s.y();
        double z = moving ? animator.z() : world.terrain().height(x, y); // a chip's ball is drawn in the air
        float[] c = PlayerColors.of(seat);
        return new BallView((float) x, (float) y, (float) Math.max(0, z), c[0], c[1], c[2]);
    }

    /** The ball rolling now (its trail is drawn), or null. */
    BallView rolling() {
        Game game = app.play().game();
        int seat = app.play().rollingSeat();
        if (game == null || seat < 0 || app.play().animator() == null) return null;
        return ball(game, seat);
    }

    /** The ball ringed as the one to play (at rest, while the game goes on), or null. */
    BallView marker() {
        Game game = app.play().game();
        if (game == null || game.isOver() || app.play().rollingSeat() >= 0 || game.currentPlayer() < 0) return null;
        return ball(game, game.currentPlayer());
    }

    /** A name tag drawn: the player's name, where its plate's bottom centre stands and its size (interface pixels), whether gold. */
    record NameTag(String name, float x, float y, float width, float height, boolean current) {
    }

    /** The tags drawn by the last {@link #nameTags()} (for tests). */
    private List<NameTag> lastTags = List.of();

    List<NameTag> lastNameTags() {
        return lastTags;
    }

    /**
     * Draws a name tag over every ball in play, the current player's in gold (for the screens that
     * show the game); tags that would cover each other are stacked (NameTagLayout).
     */
    void nameTags() {
        List<NameTag> tags = new ArrayList<>();
        lastTags = tags;
        Game game = app.play().game();
        if (game == null) return;
        double lift = 3.2 * minigolf.render.ObjectsPass.visualBallRadius();
        List<Integer> seats = new ArrayList<>();
        List<float[]> at = new ArrayList<>();
        for (int i = 0; i < game.players().size(); i++) {
            BallView b = ball(game, i);
            if (b == null) continue;
            float[] p = app.toScreen(b.x(), b.y(), b.z() + lift);
            if (p == null) continue;
            seats.add(i);
            at.add(p);
        }
        int n = seats.size(), first = -1;
        float[] x = new float[n], y = new float[n], w = new float[n], h = new float[n];
        for (int k = 0; k < n; k++) {
            float[] plate = minigolf.ui.Gui.labelPlate(game.players().get(seats.get(k)).name());
            x[k] = at.get(k)[0];
            y[k] = at.get(k)[1];
            w[k] = plate[0];
            h[k] = plate[1];
            if (seats.get(k) == game.currentPlayer() && !game.isOver()) first = k;
        }
        float[] placed = NameTagLayout.place(x, y, w, h, first);
        for (int k = 0; k < n; k++) {
            int i = seats.get(k);
            boolean current = k == first;
            float[] c = PlayerColors.of(i);
            int text = current ? abgr(0.1f, 0.08f, 0.02f, 1f) : abgr(c[0], c[1], c[2], 1f);
            int plate = current ? abgr(1f, 0.82f, 0.2f, 0.92f) : abgr(0.08f, 0.1f, 0.08f, 0.72f);
            String name = game.players().get(i).name();
            minigolf.ui.Gui.getBackgroundDrawList().addLabel(x[k], placed[k], text, plate, name);
            tags.add(new NameTag(name, x[k], placed[k], w[k], h[k], current));
        }
    }

    /** An ABGR colour (ImGui's order) from RGBA in [0, 1]. */
    static int abgr(float r, float g, float b, float a) {
        return (Math.round(a * 255) << 24) | (Math.round(b * 255) << 16) | (Math.round(g * 255) << 8) | Math.round(r * 255);
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
        scene.follow(animator != null ? animator.x() : s.x(), animator != null ? animator.y() : s.y(), animator == null, dt);
    }

    /** A final card is shown (the game or the round is over): a scripted run that waits for it may end. */
    boolean showsFinalCard() {
        return false;
    }
}
