package minigolf.app;

import java.util.Locale;
import minigolf.game.AimGuide;
import minigolf.game.AimGuideWorker;
import minigolf.game.AimModel;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.PlayerState;
import minigolf.physics.World;
import minigolf.render.AimView;
import minigolf.render.CursorRay;
import minigolf.ui.CameraDrag;
import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiDouble;
import minigolf.ui.GuiWindowFlags;
import org.joml.Vector3f;

import static org.lwjgl.glfw.GLFW.*;

/**
 * Playing a hole: the HUD, the ball in play followed by the camera, and the player's stroke. A
 * left-drag from the ball aims (slingshot: drag back, release to hit; right click cancels), the
 * wheel while aiming or Up / Down sets the loft, SPACE skips the rolling ball to its end, ESC
 * pauses. In practice mode (V, or Settings) the Shot panel hits a typed velocity. When the hole is
 * over its card is shown.
 */
class PlayingScreen extends GameScreen {
    /** How near the ball (pixels at 900 px high) a press must be to start an aim. */
    private static final double AIM_PICK_PIXELS = 48;

    private boolean aiming;
    /** The aimed velocity (vx, vy) while aiming, or null. */
    private double[] aimVelocity;
    /** The loft for the next stroke (Loft: 0 = putt, up to 60 degrees). */
    private int loft;
    /** An aim to show as soon as a human player can aim (play --aim, for screenshots), or null. */
    private double[] pendingAim;
    /** Works out the aim guide off the render thread (made at the first aim). */
    private AimGuideWorker guides;
    // The typed shot.
    private final GuiDouble typedVx = new GuiDouble(1.0);
    private final GuiDouble typedVy = new GuiDouble(0.0);
    private final GuiDouble typedVz = new GuiDouble(0.0);
    /** The chat and connection panel of an online room. */
    private final OnlinePanel onlinePanel = new OnlinePanel();

    PlayingScreen(GameApp app) {
        super(app);
    }

    /** Shows the aim (vx, vy) m/s from the first frame a human player can aim (for screenshots). */
    void showAim(double vx, double vy, int loftDegrees) {
        pendingAim = new double[]{vx, vy};
        loft = Loft.clamp(loftDegrees);
    }

    /** Whether the player may take part (false while only watching a bot). */
    boolean interactive() {
        return true;
    }

    @Override
    public void hide() {
        aiming = false;
        aimVelocity = null;
    }

    @Override
    public void update(double elapsed) {
        switch (app.play().advance(elapsed, app.timeScale(), app.settings().hideFrictionFromBots())) {
            case STROKE_ENDED -> {
                app.scene().turnToHole();
                loft = 0; // the next stroke starts as a putt again
            }
            case OVER -> app.setScreen(app.play().round() != null ? app.screens().roundCard() : app.screens().scorecard());
            case CANCELLED -> app.toMainMenu();
            case NONE -> {
            }
        }
        if (pendingAim != null && canAim()) {
            aiming = true;
            aimVelocity = pendingAim;
            pendingAim = null;
        }
    }

    /** A person is to play and may aim now. */
    boolean canAim() {
        return interactive() && app.play().humanToPlay();
    }

    @Override
    public void render(float w, float h) {
        nameTags();
        app.hud().render(w, h, aimSpeed(), loft);
        if (showsShotPanel()) shotPanel(w, h);
        if (app.play().online() != null) onlinePanel.render(app.play().online(), w, h);
    }

    /** The typed-velocity Shot panel is lab furniture: practice mode only, on a person's turn. */
    boolean showsShotPanel() {
        return app.settings().practice() && canAim() && app.play().botTurn() == null;
    }

    /** The aim being dragged: speed in m/s, or negative when not aiming. */
    double aimSpeed() {
        return aiming && aimVelocity != null ? Math.hypot(aimVelocity[0], aimVelocity[1]) : -1;
    }

    int loftDegrees() {
        return loft;
    }

    private void shotPanel(float w, float h) {
        double max = app.play().world().physics().maxSpeed();
        Gui.setNextWindowPos(w - 12, h - 12, GuiCond.Always, 1f, 1f);
        Gui.begin("Shot", GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        Gui.text("Drag back from the ball to aim, release to hit,");
        Gui.text("or type the velocity (max " + max + " m/s):");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vx", typedVx, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vy", typedVy, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vz (0 = putt)", typedVz, 0.1, 0.5, "%.3f");
        double speed = Math.sqrt(typedVx.get() * typedVx.get() + typedVy.get() * typedVy.get() + typedVz.get() * typedVz.get());
        Gui.progressBar((float) Math.min(1, speed / max), 240, 0, String.format(Locale.ROOT, "%.2f m/s", speed));
        String problem = AimModel.checkTyped(typedVx.get(), typedVy.get(), typedVz.get(), max);
        if (problem != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, problem);
        if (problem != null) Gui.beginDisabled();
        if (Gui.button("HIT", 120, 0)) hit(typedVx.get(), typedVy.get(), typedVz.get());
        if (problem != null) Gui.endDisabled();
        double aim = aimSpeed();
        if (aim >= 0) Gui.progressBar((float) (aim / max), 240, 0, String.format(Locale.ROOT, "power %.2f m/s", aim));
        Gui.end();
    }

    private void hit(double vx, double vy, double vz) {
        app.play().hit(vx, vy, vz);
        loft = 0; // the next stroke starts as a putt again
    }

    @Override
    AimView aim() {
        Game game = app.play().game();
        if (!aiming || aimVelocity == null || game == null || game.currentPlayer() < 0) return null;
        World world = app.play().world();
        double speed = Math.hypot(aimVelocity[0], aimVelocity[1]);
        if (speed < 1e-6) return null;
        PlayerState s = game.player(game.currentPlayer());
        double[] v = Loft.velocity(aimVelocity[0], aimVelocity[1], loft, world.physics().maxSpeed());
        return new AimView((float) s.x(), (float) s.y(), (float) world.terrain().height(s.x(), s.y()),
                (float) aimVelocity[0], (float) aimVelocity[1], (float) (speed / world.physics().maxSpeed()),
                app.settings().aimGuide() ? guidePath(game, s.x(), s.y(), v) : null);
    }

    /**
     * The aim guide (AimGuide: the real engine, the game's settings, a chip's flight too), the whole
     * putt until it stops or drops: worked out on the guide's own thread, so a frame never waits for
     * it; until the new aim's path is ready the last one shows (the same array, so the arrow is not rebuilt).
     * Where obstacles move it is the stroke hit now, at the clock a release would start it at.
     */
    private float[] guidePath(Game game, double x, double y, double[] v) {
        if (guides == null) guides = new AimGuideWorker();
        AimGuide g = guides.guide(game.world(), game.settings(), x, y, v[0], v[1], v[2], app.play().shotClock());
        return g == null ? null : g.points();
    }

    @Override
    public void dispose() {
        if (guides != null) guides.close();
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        switch (key) {
            case GLFW_KEY_ESCAPE -> app.setScreen(app.screens().pause());
            case GLFW_KEY_UP, GLFW_KEY_DOWN -> loft = stepLoft(key == GLFW_KEY_UP ? 1 : -1);
            case GLFW_KEY_SPACE -> app.play().skipAnimation(); // the same stroke, run to its end
            case GLFW_KEY_V -> { // practice mode: the typed-velocity Shot panel and the physics readout
                boolean on = !app.settings().practice();
                app.applySettings(app.settings().withPractice(on));
                app.say(on ? "Practice mode: type a shot's velocity, see the ball's physics (V turns it off)"
                        : "Practice mode off");
            }
            default -> {
                return false;
            }
        }
        return true;
    }

    @Override
    public boolean mouseButton(int button, boolean down, int mods, double x, double y) {
        if (aiming) {
            if (button == GLFW_MOUSE_BUTTON_LEFT && !down) {
                aiming = false;
                double[] v = aimVelocity;
                aimVelocity = null;
                if (v != null && Math.hypot(v[0], v[1]) > 0.02) {
                    double[] shot = Loft.velocity(v[0], v[1], loft, app.play().world().physics().maxSpeed());
                    hit(shot[0], shot[1], shot[2]);
                }
            } else if (button == GLFW_MOUSE_BUTTON_RIGHT && down) {
                aiming = false; // right click cancels the aim
                aimVelocity = null;
            }
            return true; // while aiming the camera stays put
        }
        if (button == GLFW_MOUSE_BUTTON_LEFT && down && CameraDrag.of(button, mods) == CameraDrag.NONE && canAim()
                && nearBall(x, y)) {
            aiming = true;
            aimVelocity = null;
            return true;
        }
        return false;
    }

    @Override
    public boolean cursorMoved(double x, double y) {
        if (!aiming) return false;
        aimVelocity = aimFromCursor(x, y);
        return true;
    }

    @Override
    public boolean scrolled(double dy) {
        if (!aiming) return false;
        loft = stepLoft((int) Math.signum(dy)); // while aiming the wheel lofts the shot
        return true;
    }

    /** The loft after {@code notches} steps; always a putt on a course that plays putts only (a classic track). */
    private int stepLoft(int notches) {
        return app.play().world().physics().puttsOnly() ? 0 : Loft.step(loft, notches);
    }

    private boolean nearBall(double x, double y) {
        Game game = app.play().game();
        PlayerState s = game.player(game.currentPlayer());
        int fw = app.window().framebufferWidth(), fh = app.window().framebufferHeight();
        World world = app.play().world();
        float[] p = app.scene().camera().project(new Vector3f((float) s.x(), (float) s.y(),
                (float) world.terrain().height(s.x(), s.y())), fw, fh);
        double[] c = app.toFramebuffer(x, y);
        return p != null && Math.hypot(p[0] - c[0], p[1] - c[1]) <= AIM_PICK_PIXELS * Math.max(1, fh / 900.0);
    }

    /** Where the cursor ray meets the horizontal plane through the ball, turned into a shot. */
    private double[] aimFromCursor(double x, double y) {
        Game game = app.play().game();
        PlayerState s = game.player(game.currentPlayer());
        World world = app.play().world();
        double[] c = app.toFramebuffer(x, y), p = CursorRay.onPlane(app.scene().camera(), app.window().framebufferWidth(),
                app.window().framebufferHeight(), c[0], c[1], world.terrain().height(s.x(), s.y()));
        if (p == null) return aimVelocity;
        return AimModel.velocityForPull(s.x(), s.y(), p[0], p[1], world.physics().maxSpeed(), AimModel.DEFAULT_FULL_PULL);
    }
}
