package minigolf.app;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import minigolf.render.AimView;
import minigolf.render.BallTrail;
import minigolf.render.CameraClearance;
import minigolf.render.BallView;
import minigolf.render.CupDrop;
import minigolf.render.OrbitCamera;
import minigolf.render.Particles;
import minigolf.render.RenderQuality;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import org.joml.Vector3f;

/**
 * The course in 3D behind every screen: the renderer, built again whenever another course is
 * shown or the graphics settings change; the camera, which glides after the ball in play, swings
 * round behind the next ball to face the hole, or turns slowly round the whole course behind a
 * final card; the effects (confetti, splashes, the ball dropping into the cup); the minimap.
 */
final class CourseScene implements AutoCloseable {
    /**
     * The final card's view: its pitch, its turn (radians per second), and the course's middle
     * right of the screen's, clear of the card at the left ({@code Panels.leftOfCourse}).
     */
    static final float CARD_PITCH = (float) Math.toRadians(40), CARD_TURN = 0.08f, CARD_SHIFT_X = 0.42f;

    /** Confetti and splashes (the renderer draws them; they end by themselves). */
    private final Particles effects = new Particles();
    /** The holed ball sinking into the cup (drawn until it is out of sight). */
    private final CupDrop cupDrop = new CupDrop();
    /** Where the rolling ball was over the last half second. */
    private final BallTrail trail = new BallTrail();
    private SceneRenderer renderer;
    private OrbitCamera camera;
    private World built;
    private boolean stale = true;
    private RenderQuality quality = RenderQuality.HIGH;
    /** What the renderer probed as right for this machine (the "auto" graphics setting). */
    private RenderQuality autoQuality = RenderQuality.HIGH;

    private final Vector3f followTarget = new Vector3f();
    /** Set when a stroke ends: the camera turns towards the hole until it faces it or the player turns it. */
    private boolean turnToHole;
    /** The player is turning or moving the camera: it follows nothing meanwhile. */
    private boolean playerMoves;
    /** The final card's view has been set up (it turns from there), and the clearance and picture shifts it set aside. */
    private boolean onCard;
    private CameraClearance cardClearance;
    private float[] cardShift;
    private float lastDrawTime = Float.NaN;

    /** Probes the machine once the window's GL context exists; the player's setting picks from there. */
    void probeQuality(UserSettings s) {
        autoQuality = RenderQuality.probe(); // llvmpipe: no MSAA, smaller water targets (docs/rendering.md)
        quality = chosenQuality(s);
    }

    RenderQuality quality() {
        return quality;
    }

    /** The renderer's quality for the player's graphics setting: auto is what the probe found. */
    RenderQuality chosenQuality(UserSettings s) {
        return switch (s.graphics()) {
            case "high" -> RenderQuality.HIGH;
            case "low" -> RenderQuality.SOFTWARE;
            default -> autoQuality;
        };
    }

    /** New settings: a new graphics quality builds the scene again at the next frame; FXAA switches at once. */
    void applySettings(UserSettings old, UserSettings now) {
        if (!now.graphics().equals(old.graphics())) {
            quality = chosenQuality(now); // multisampling stays as the window was made (next start)
            stale = true;
        }
        if (renderer != null) renderer.setAntiAliasing(now.antiAliasing() && quality.samples() == 0);
    }

    /** Shows {@code world} (its course file's folder holds the models' colours, may be null); builds the scene when it is another. */
    /** The bricks drawn now and on which course (see {@link #showBricks}). */
    private minigolf.physics.CourseState drawnBricks;
    private World bricksOf;

    void show(World world, Path coursePath, UserSettings settings, int width, int height) {
        if (!stale && world == built) return;
        stale = false;
        built = world;
        effects.clear(); // a new hole: the last one's confetti stays behind
        trail.clear();
        cupDrop.clear();
        if (renderer != null) renderer.close();
        renderer = null;
        renderer = new SceneRenderer(world.course(), world.terrain(),
                settings.heightColours() ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN, quality);
        if (coursePath != null) renderer.setCourseFolder(coursePath.toAbsolutePath().getParent());
        renderer.setAntiAliasing(settings.antiAliasing() && quality.samples() == 0); // FXAA only without MSAA
        // Behind the ball, facing the hole, steeper where the windmill would hide the cup.
        camera = OrbitCamera.opening(world.course(), world.terrain(), (float) Math.max(1, width) / Math.max(1, height));
        followTarget.set(camera.target());
        onCard = false; // a new camera, with its own clearance
        cardClearance = null;
    }

    SceneRenderer renderer() {
        return renderer;
    }

    OrbitCamera camera() {
        return camera;
    }

    Particles effects() {
        return effects;
    }

    CupDrop cupDrop() {
        return cupDrop;
    }

    /** The course shown now (null before the first frame). */
    /**
     * Draws the breakable bricks that {@code state} leaves standing (null: every brick, as the hole
     * starts); the obstacles are rebuilt only when that changes.
     */
    void showBricks(minigolf.physics.CourseState state) {
        World w = built;
        if (w == null || renderer == null || w.course().bricks().isEmpty()) return;
        minigolf.physics.CourseState s = state != null && state.bricks() == w.course().bricks().size() ? state
                : minigolf.physics.CourseState.initial(w.course());
        if (s.equals(drawnBricks) && w == bricksOf) return;
        drawnBricks = s;
        bricksOf = w;
        renderer.setObstacles(w.course().obstaclesWithBricks(s::standing));
    }

    World world() {
        return built;
    }

    void resetCamera() {
        if (camera != null) camera.reset();
    }

    /** A stroke ended: swing round behind the next ball, facing the hole. */
    void turnToHole() {
        turnToHole = true;
    }

    /** The player turns or moves the camera himself: it stops following and turning. */
    void playerMoves(boolean moving) {
        playerMoves = moving;
        if (moving) turnToHole = false;
    }

    /** The course clock the moving obstacles are drawn at. */
    void setClock(double clock) {
        if (renderer != null) renderer.setClock(clock);
    }

    /**
     * Draws the scene with these balls and aim, the ring round the ball to play ({@code marker},
     * may be null) and the trail behind the ball rolling ({@code rolling}, may be null), then the
     * minimap at the top right.
     */
    void draw(int fw, int fh, float time, List<BallView> balls, AimView aim, BallView marker, BallView rolling) {
        cupDrop.advanceTo(time);
        renderer.setBalls(balls);
        renderer.setAim(aim);
        renderer.setMarker(marker);
        if (rolling == null) {
            trail.clear();
        } else {
            trail.add(time, rolling.x(), rolling.y(), rolling.z());
        }
        renderer.setTrail(trail.isEmpty() ? null : trail.path(),
                rolling == null ? null : new float[]{rolling.red(), rolling.green(), rolling.blue()});
        effects.advanceTo(time);
        renderer.setEffects(effects.mesh());
        camera.ease(time - lastDrawTime > 0 ? time - lastDrawTime : 0); // the clearance's moves glide
        lastDrawTime = time;
        renderer.render(camera, fw, fh, time);
        int mini = Math.min(fw, fh) / 4;
        renderer.renderMinimap(fw - mini - 12, 12, mini, fw, fh);
    }

    /** Seconds since the frame before (0 for the first). */
    float sinceLastFrame(float time) {
        return Float.isNaN(lastDrawTime) ? 0 : time - lastDrawTime;
    }

    /**
     * The camera glides after the point (x, y) on the ground (the ball in play); once the balls
     * are at rest after a stroke it swings round behind it, looking at the hole. {@code dt}: seconds
     * since the last frame, so the glide takes as long at 20 frames a second as at 144.
     */
    void follow(double x, double y, boolean atRest, float dt) {
        leaveOverview();
        if (playerMoves) return;
        World world = built;
        followTarget.set((float) x, (float) y, (float) world.terrain().height(x, y));
        Vector3f t = camera.target();
        t.lerp(followTarget, glide(0.12f, dt));
        camera.setTarget(t);
        if (turnToHole && atRest) {
            // The nearest hole: on a course with several (the classic tracks), the one most likely played for.
            var hole = world.nearestHole(x, y).position();
            double hx = hole.x() - x, hy = hole.y() - y;
            if (Math.hypot(hx, hy) < 1e-6) {
                turnToHole = false;
                return;
            }
            double want = Math.atan2(-hy, -hx), delta = Math.IEEEremainder(want - camera.yaw(), 2 * Math.PI);
            camera.rotate((float) (delta * glide(0.1f, dt)), 0);
            if (Math.abs(delta) < 0.005) turnToHole = false;
        }
    }

    /**
     * The share of the way left that a glide covers in {@code dt} seconds, when it covers
     * {@code perFrame} of it in one frame at 60 frames a second: the same glide at any frame rate
     * (it used to move {@code perFrame} a frame, so a slow machine's camera lagged seconds behind).
     */
    static float glide(float perFrame, float dt) {
        return (float) (1 - Math.pow(1 - perFrame, Math.max(0, dt) * 60));
    }

    /** The camera stays where it is (menus over the course). */
    void hold() {
        leaveOverview();
    }

    /**
     * Behind a final card the camera leaves the last ball (a view that a tree beside it could tip
     * steeply down onto the green) for the whole course: it cuts to the course's middle at
     * {@link #CARD_PITCH} and a distance that frames the course from every side, then turns slowly
     * round it. Following a ball again brings the ball-following camera back.
     */
    void overview(float dt, float aspect) {
        if (playerMoves) return;
        if (!onCard) {
            World world = built;
            minigolf.course.Bounds b = world.course().bounds();
            double cx = 0.5 * (b.minX() + b.maxX()), cy = 0.5 * (b.minY() + b.maxY());
            camera.setTarget(new Vector3f((float) cx, (float) cy, (float) Math.max(0, world.terrain().height(cx, cy))));
            camera.rotate(0, CARD_PITCH - camera.pitch());
            cardShift = new float[]{camera.screenShiftX(), camera.screenShiftY()};
            camera.setScreenShiftX(CARD_SHIFT_X);
            camera.setScreenShiftY(0);
            camera.frameFromAllSides(world.course(), world.terrain(), aspect, 0.92f);
            // The overview looks at the whole course, not at a ball a tree could hide: from that far the
            // clearance would only pull the eye into the crowns round the middle.
            cardClearance = camera.clearance();
            camera.setClearance(null);
            onCard = true;
        }
        camera.rotate(CARD_TURN * dt, 0);
    }

    private void leaveOverview() {
        if (!onCard) return;
        camera.setClearance(cardClearance);
        camera.setScreenShiftX(cardShift[0]);
        camera.setScreenShiftY(cardShift[1]);
        onCard = false;
    }

    @Override
    public void close() {
        if (renderer != null) renderer.close();
        renderer = null;
    }
}
