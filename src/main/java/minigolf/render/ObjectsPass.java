package minigolf.render;

import minigolf.course.Course;
import minigolf.terrain.Terrain;
import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;

import java.util.List;

import static org.lwjgl.opengl.GL11.*;

/** The hole (cup and flag), the other holes (cups), the balls and the aiming arrow. */
public final class ObjectsPass implements RenderPass {
    /** A golf ball's radius in metres. */
    public static final double BALL_RADIUS = 0.02135;
    /** The ball is drawn this much larger than it is, so that it can be seen from the opening view. */
    public static final double BALL_VISUAL_SCALE = 3.0;
    public static final double FLAG_HEIGHT = 1.0;
    public static final double POLE_RADIUS = 0.012;
    /** How deep the flag model's foot (its origin) stands in the cup: models/flag.obj's pole is 1.05 m long. */
    static final double FLAG_FOOT_DEPTH = 0.05;
    /** The aiming arrow's length at no power and its extra length at full power, in metres. */
    public static final double ARROW_MIN_LENGTH = 0.3, ARROW_POWER_LENGTH = 1.7;

    private final Terrain terrain;
    private final double holeX, holeY;
    private final LitShader shader;
    private ShaderProgram program;
    private final Mesh cupRim;
    private final Mesh cup;
    /** The course's extra holes (the classic tracks'): a rim and a cup each, no flag; their centres in extraX, extraY. */
    private final Mesh[] extraRims, extraCups;
    private final double[] extraX, extraY;
    /** The flagstick (models/flag.obj: pole, gold ball, waving cloth), placed at the hole. */
    private final Mesh flag;
    /** Confetti and splashes (Particles), rebuilt each frame while they last; null when none. */
    private Mesh effects;
    private final Mesh ball;
    private final Mesh mapBall;
    private final List<BallView> defaultBalls;
    private List<BallView> balls;
    private AimView aim;
    private Mesh arrow;
    /** The ring round the current player's ball, and the ball it was built for (null: none). */
    private Mesh marker;
    private BallView markerFor;
    /** The rolling ball's trail, rebuilt each frame it changes; null when none. */
    private Mesh trail;
    private final Matrix4f model = new Matrix4f();
    private final Matrix3f normalMatrix = new Matrix3f();

    public ObjectsPass(Course course, Terrain terrain) {
        this(course, terrain, false);
    }

    /** As above; {@code vertexLit} picks the software rasterisers' shader (object-vertexlit: lighting per vertex). */
    public ObjectsPass(Course course, Terrain terrain, boolean vertexLit) {
        this.shader = new LitShader(vertexLit ? "object-vertexlit" : "object");
        this.terrain = terrain;
        holeX = course.hole().position().x();
        holeY = course.hole().position().y();
        double hx = holeX, hy = holeY, r = course.hole().radius();
        double ground = terrain.height(hx, hy);
        // The software tier pays per triangle (llvmpipe sets each up on one thread): a rounder cup and
        // ball than a few pixels of them can show cost it more than the whole sky.
        int cupSegments = vertexLit ? 24 : 48;
        cupRim = new Mesh(Shapes.drapedDisc(hx, hy, r * 1.15, cupSegments, 3, terrain::height, 0.003, 0.92f, 0.92f, 0.88f));
        cup = new Mesh(Shapes.drapedDisc(hx, hy, r, cupSegments, 3, terrain::height, 0.005, 0.03f, 0.04f, 0.03f));
        int extra = course.extraHoles().size();
        extraRims = new Mesh[extra];
        extraCups = new Mesh[extra];
        extraX = new double[extra];
        extraY = new double[extra];
        for (int i = 0; i < extra; i++) {
            var h = course.extraHoles().get(i);
            extraX[i] = h.position().x();
            extraY[i] = h.position().y();
            extraRims[i] = new Mesh(Shapes.drapedDisc(extraX[i], extraY[i], h.radius() * 1.15, cupSegments, 3, terrain::height,
                    0.003, 0.92f, 0.92f, 0.88f));
            extraCups[i] = new Mesh(Shapes.drapedDisc(extraX[i], extraY[i], h.radius(), cupSegments, 3, terrain::height,
                    0.005, 0.03f, 0.04f, 0.03f));
        }
        // The cloth flies sideways to the line from the start to the hole, so the opening view sees it broadside.
        flag = new Mesh(ModelResource.get("flag").placed(hx, hy, ground - FLAG_FOOT_DEPTH,
                clothHeading(course.start().x(), course.start().y(), hx, hy), 1));
        // 1,280 triangles; the software tier's ball 320 (lit per vertex, a ball 25 pixels across shows no
        // facet), and the minimap's balls, a few pixels across, 80.
        ball = new Mesh(Shapes.icosphere(vertexLit ? 2 : 3, 1f, 1f, 1f));
        mapBall = vertexLit ? new Mesh(Shapes.icosphere(1, 1f, 1f, 1f)) : ball;
        double bx = course.start().x(), by = course.start().y();
        defaultBalls = List.of(BallView.white(bx, by, terrain.height(bx, by)));
        balls = defaultBalls;
    }

    /** The cloth's heading in degrees (the model's +x turned about z): sideways to the line from the start to the hole. */
    static double clothHeading(double startX, double startY, double holeX, double holeY) {
        double dx = holeX - startX, dy = holeY - startY;
        if (Math.hypot(dx, dy) < 1e-9) return 0;
        return Math.toDegrees(Math.atan2(-dx, dy));
    }

    /** Puts a single white ball at rest on the surface at (x, y). */
    public void setBall(double x, double y) {
        balls = List.of(BallView.white(x, y, terrain.height(x, y)));
    }

    /** The balls to draw; null restores the default (one white ball at the course start), empty draws none. */
    public void setBalls(List<BallView> views) {
        balls = views == null ? defaultBalls : List.copyOf(views);
    }

    public List<BallView> balls() {
        return balls;
    }

    /** The effects' particles to draw this frame ({@link Particles#mesh()}), or null for none. */
    public void setEffects(MeshData particles) {
        if (effects != null) {
            effects.close();
            effects = null;
        }
        if (particles != null && particles.triangleCount() > 0) effects = new Mesh(particles);
    }

    /** Whether effect particles are being drawn. */
    public boolean hasEffects() {
        return effects != null;
    }

    /** Shows the aiming arrow, or hides it for null. The arrow mesh is rebuilt only when the aim changes. */
    public void setAim(AimView view) {
        if (view != null && view.equals(aim)) return;
        if (arrow != null) {
            arrow.close();
            arrow = null;
        }
        aim = view;
        if (view != null) arrow = new Mesh(arrowMesh(view, terrain));
    }

    public AimView aim() {
        return aim;
    }

    /** Rings {@code ball} (the current player's) in gold on the ground, or shows no ring for null. */
    public void setMarker(BallView ball) {
        if (ball == null ? markerFor == null : ball.equals(markerFor)) return;
        if (marker != null) marker.close();
        marker = null;
        markerFor = ball;
        if (ball != null) marker = new Mesh(markerMesh(ball, terrain));
    }

    /** The ball that is ringed, or null. */
    public BallView marker() {
        return markerFor;
    }

    /** The gold ring: just outside the drawn ball, on the ground (or the water's surface) under it. */
    static MeshData markerMesh(BallView ball, Terrain terrain) {
        double r = visualBallRadius();
        return Shapes.drapedRing(ball.x(), ball.y(), 1.35 * r, 1.8 * r, 32, (x, y) -> Math.max(0, terrain.height(x, y)),
                0.006, 1f, 0.82f, 0.2f);
    }

    /** The trail behind a rolling ball ({@link BallTrail#path()}) in the ball's colour; null or a short path draws none. */
    public void setTrail(float[] path, float[] rgb) {
        if (trail != null) trail.close();
        trail = null;
        if (path == null || path.length < 6) return;
        MeshData m = Shapes.trail(path, 0.45 * visualBallRadius(), (x, y, z) -> Math.max(Math.max(0, z),
                terrain.height(x, y)) + 0.004, rgb[0], rgb[1], rgb[2]);
        if (m != null) trail = new Mesh(m);
    }

    public boolean hasTrail() {
        return trail != null;
    }

    /** The arrow for an aim: draped over the ground (or the water surface), coloured by power; and the guide's dots. */
    static MeshData arrowMesh(AimView view, Terrain terrain) {
        float power = Math.max(0f, Math.min(1f, view.power01()));
        float[] c = powerColor(power);
        double start = visualBallRadius() * 1.3;
        double length = start + ARROW_MIN_LENGTH + ARROW_POWER_LENGTH * power;
        MeshData arrow = Shapes.groundArrow(view.x(), view.y(), view.dirX(), view.dirY(), start, length, 0.06,
                (x, y) -> Math.max(0, terrain.height(x, y)), 0.012, c[0], c[1], c[2]);
        if (view.guide() == null || view.guide().length < 6) return arrow;
        // White dots every GUIDE_SPACING along the guide, past the ball; on water they float on its surface.
        MeshData dots = Shapes.dotsAlong(view.guide(), GUIDE_SPACING, visualBallRadius() * 2.2, GUIDE_DOT_RADIUS,
                (x, y, z) -> Math.max(0, z) + 0.008, 0.97f, 0.97f, 0.92f);
        return dots == null ? arrow : MeshData.concat(arrow, dots);
    }

    /** The aim guide's dots: their spacing along the path and their radius, in metres. */
    static final double GUIDE_SPACING = 0.14, GUIDE_DOT_RADIUS = 0.032;

    /** Green at no power, yellow at half, red at full. */
    public static float[] powerColor(float power01) {
        float t = Math.max(0f, Math.min(1f, power01));
        if (t < 0.5f) {
            float u = t / 0.5f;
            return new float[]{0.15f + 0.80f * u, 0.80f + 0.05f * u, 0.15f - 0.05f * u};
        }
        float u = (t - 0.5f) / 0.5f;
        return new float[]{0.95f - 0.05f * u, 0.85f - 0.73f * u, 0.10f - 0.02f * u};
    }

    public static double visualBallRadius() {
        return BALL_RADIUS * BALL_VISUAL_SCALE;
    }

    /** The centre of the first ball drawn (the default: the ball at the course start). */
    public Vector3f ballCenter() {
        BallView b = balls.isEmpty() ? defaultBalls.get(0) : balls.get(0);
        return new Vector3f(b.x(), b.y(), b.z() + (float) visualBallRadius());
    }

    @Override
    public void render(FrameContext frame) {
        begin(frame);
        draw(cupRim, model.identity(), 0.15f, 16f);
        draw(cup, model.identity(), 0.0f, 8f);
        for (int i = 0; i < extraCups.length; i++) {
            draw(extraRims[i], model.identity(), 0.15f, 16f);
            draw(extraCups[i], model.identity(), 0.0f, 8f);
        }
        program.set("uFlagPole", (float) holeX, (float) holeY);
        draw(flag, model.identity(), 0.3f, 32f);
        if (arrow != null) draw(arrow, model.identity(), 0.2f, 16f);
        if (marker != null) draw(marker, model.identity(), 0.3f, 16f);
        if (trail != null) draw(trail, model.identity(), 0.1f, 8f);
        drawBalls(ball, (float) visualBallRadius());
        if (effects != null) draw(effects, model.identity(), 0.4f, 24f);
    }

    /**
     * The objects again for the balls' shadows' second draw (SceneRenderer, software tier): as
     * {@link #render}, but a single ball is left out, since no ball shades itself (shadow.glsl skips
     * the caster's own surface) and its pixels are already drawn.
     */
    void renderForBallShadows(FrameContext frame) {
        if (balls.size() > 1) {
            render(frame);
            return;
        }
        List<BallView> all = balls;
        balls = List.of();
        try {
            render(frame);
        } finally {
            balls = all;
        }
    }

    /**
     * The minimap's objects, seen from above and drawn over the terrain: the hole enlarged to
     * {@code markerRadius} and the balls at least that big, so both read at a few pixels per metre.
     */
    void renderMinimap(FrameContext frame, float markerRadius) {
        glDisable(GL_DEPTH_TEST);
        begin(frame);
        float s = (float) Math.max(1, markerRadius / 0.12);
        model.translation((float) holeX, (float) holeY, 0).scale(s, s, 1).translate((float) -holeX, (float) -holeY, 0);
        draw(cupRim, model, 0.0f, 8f);
        draw(cup, model, 0.0f, 8f);
        for (int i = 0; i < extraCups.length; i++) {
            float x = (float) extraX[i], y = (float) extraY[i];
            model.translation(x, y, 0).scale(s, s, 1).translate(-x, -y, 0);
            draw(extraRims[i], model, 0.0f, 8f);
            draw(extraCups[i], model, 0.0f, 8f);
        }
        drawBalls(mapBall, Math.max((float) visualBallRadius(), markerRadius));
        glEnable(GL_DEPTH_TEST);
    }

    /** Draws what casts sun shadows and stands still (pole, flag) with the depth-only shader. */
    void drawShadowCasters(ShaderProgram depthShader) {
        depthShader.set("uModel", model.identity());
        flag.draw();
    }

    /** Puts the balls (centre, radius) into the frame as analytic shadow casters; returns how many fit. */
    int ballShadows(FrameContext frame) {
        float radius = (float) visualBallRadius();
        int n = Math.min(balls.size(), FrameContext.MAX_BALL_SHADOWS);
        for (int i = 0; i < n; i++) {
            BallView b = balls.get(i);
            frame.ballShadows[4 * i] = b.x();
            frame.ballShadows[4 * i + 1] = b.y();
            frame.ballShadows[4 * i + 2] = b.z() + radius;
            frame.ballShadows[4 * i + 3] = radius;
        }
        frame.ballShadowCount = n;
        return n;
    }

    private void begin(FrameContext frame) {
        program = shader.use(frame);
        program.set("uViewProjection", frame.viewProjection);
        program.set("uClipPlane", frame.clipPlane);
    }

    private void drawBalls(Mesh sphere, float radius) {
        for (BallView b : balls) {
            model.translation(b.x(), b.y(), b.z() + radius).scale(radius);
            draw(sphere, model, 0.6f, 64f, b.red(), b.green(), b.blue());
        }
    }

    private void draw(Mesh mesh, Matrix4f m, float specular, float shininess) {
        draw(mesh, m, specular, shininess, 1f, 1f, 1f);
    }

    private void draw(Mesh mesh, Matrix4f m, float specular, float shininess, float r, float g, float b) {
        program.set("uModel", m);
        program.set("uNormalMatrix", m.normal(normalMatrix));
        program.set("uSpecularStrength", specular);
        program.set("uShininess", shininess);
        program.set("uTint", r, g, b);
        mesh.draw();
    }

    @Override
    public void close() {
        cupRim.close();
        cup.close();
        for (int i = 0; i < extraCups.length; i++) {
            extraRims[i].close();
            extraCups[i].close();
        }
        flag.close();
        ball.close();
        mapBall.close();
        if (arrow != null) arrow.close();
        if (effects != null) effects.close();
        if (marker != null) marker.close();
        if (trail != null) trail.close();
        shader.close();
    }
}
