package minigolf.render;

import minigolf.course.Course;
import minigolf.terrain.Terrain;
import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;

/** The hole (cup and flag) and the ball. */
public final class ObjectsPass implements RenderPass {
    /** A golf ball's radius in metres. */
    public static final double BALL_RADIUS = 0.02135;
    /** The ball is drawn this much larger than it is, so that it can be seen from the opening view. */
    public static final double BALL_VISUAL_SCALE = 3.0;
    public static final double FLAG_HEIGHT = 1.0;
    public static final double POLE_RADIUS = 0.012;

    private final Terrain terrain;
    private final ShaderProgram shader = ShaderProgram.load("object");
    private final Mesh cupRim;
    private final Mesh cup;
    private final Mesh pole;
    private final Mesh cloth;
    private final Mesh ball;
    private final Vector3f ballCenter = new Vector3f();
    private final Matrix4f model = new Matrix4f();
    private final Matrix3f normalMatrix = new Matrix3f();

    public ObjectsPass(Course course, Terrain terrain) {
        this.terrain = terrain;
        double hx = course.hole().position().x(), hy = course.hole().position().y(), r = course.hole().radius();
        double ground = terrain.height(hx, hy);
        cupRim = new Mesh(Shapes.drapedDisc(hx, hy, r * 1.15, 48, 3, terrain::height, 0.003, 0.92f, 0.92f, 0.88f));
        cup = new Mesh(Shapes.drapedDisc(hx, hy, r, 48, 3, terrain::height, 0.005, 0.03f, 0.04f, 0.03f));
        double top = ground + FLAG_HEIGHT;
        pole = new Mesh(Shapes.cylinder(hx, hy, ground - 0.05, top, POLE_RADIUS, 12, 0.95f, 0.95f, 0.93f));
        // The cloth flies sideways to the line from the start to the hole, so the opening view sees it broadside.
        double dx = hx - course.start().x(), dy = hy - course.start().y(), len = Math.hypot(dx, dy);
        double sx = len > 1e-9 ? dy / len : 1, sy = len > 1e-9 ? -dx / len : 0;
        double w = 0.42, hgt = 0.26;
        cloth = new Mesh(Shapes.triangle(new double[]{hx, hy, top}, new double[]{hx, hy, top - hgt},
                new double[]{hx + sx * w, hy + sy * w, top - hgt * 0.5}, 0.86f, 0.08f, 0.06f));
        ball = new Mesh(Shapes.icosphere(3, 1f, 1f, 1f));
        setBall(course.start().x(), course.start().y());
    }

    /** Puts the ball at rest on the surface at (x, y). */
    public void setBall(double x, double y) {
        ballCenter.set((float) x, (float) y, (float) (terrain.height(x, y) + visualBallRadius()));
    }

    public static double visualBallRadius() {
        return BALL_RADIUS * BALL_VISUAL_SCALE;
    }

    public Vector3f ballCenter() {
        return new Vector3f(ballCenter);
    }

    @Override
    public void render(FrameContext frame) {
        shader.use();
        shader.set("uViewProjection", frame.viewProjection);
        Lighting.apply(shader, frame);
        draw(cupRim, model.identity(), 0.15f, 16f);
        draw(cup, model.identity(), 0.0f, 8f);
        draw(pole, model.identity(), 0.4f, 48f);
        draw(cloth, model.identity(), 0.1f, 8f);
        float r = (float) visualBallRadius();
        draw(ball, model.translation(ballCenter).scale(r), 0.6f, 64f);
    }

    private void draw(Mesh mesh, Matrix4f m, float specular, float shininess) {
        shader.set("uModel", m);
        shader.set("uNormalMatrix", m.normal(normalMatrix));
        shader.set("uSpecularStrength", specular);
        shader.set("uShininess", shininess);
        mesh.draw();
    }

    @Override
    public void close() {
        cupRim.close();
        cup.close();
        pole.close();
        cloth.close();
        ball.close();
        shader.close();
    }
}
