package minigolf.render;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;
import org.joml.Matrix3f;
import org.joml.Matrix4f;

/**
 * Draws the course elements of issue 24 ({@link ElementMeshes}): bumpers, one-way gates, push
 * zones, magnets, teleports, and the moving obstacles at the course clock's moment, each body's
 * mesh moved by its motion's pose every frame, so they move smoothly. The teleports' pads and the
 * bumpers' caps glow (drawn brighter, pulsing with the time). Rebuilt by {@link #setCourse} when
 * the editor changes the course.
 */
public final class ElementsPass implements RenderPass {
    private final HeightProbe ground;
    private final LitShader shader;
    private final Matrix4f identity = new Matrix4f();
    private final Matrix4f model = new Matrix4f();
    private final Matrix3f normalMatrix = new Matrix3f();
    private final double[] pose = new double[12];
    private Mesh solid, decals, glow;
    private final List<Mesh> moving = new ArrayList<>();
    private List<Obstacle.Moving> movers = List.of();
    private double clock;

    public ElementsPass(Course course, HeightProbe ground, boolean vertexLit) {
        this.ground = ground;
        this.shader = new LitShader(vertexLit ? "object-vertexlit" : "object");
        try {
            setCourse(course);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /** Rebuilds the meshes from the course's elements. */
    public void setCourse(Course course) {
        ElementMeshes.Built built = ElementMeshes.build(course, ground);
        free();
        solid = mesh(built.solid());
        decals = mesh(built.decals());
        glow = mesh(built.glow());
        for (MeshData d : built.moving()) moving.add(mesh(d));
        movers = built.movers();
    }

    /** The course clock (s) the moving obstacles are drawn at. */
    public void setClock(double clock) {
        this.clock = clock;
    }

    public double clock() {
        return clock;
    }

    /** Whether there is anything to draw. */
    public boolean isEmpty() {
        return solid == null && decals == null && glow == null && moving.isEmpty();
    }

    private static Mesh mesh(MeshData d) {
        return d.triangleCount() > 0 ? new Mesh(d) : null;
    }

    @Override
    public void render(FrameContext frame) {
        if (isEmpty()) return;
        ShaderProgram program = shader.use(frame);
        program.set("uViewProjection", frame.viewProjection);
        program.set("uClipPlane", frame.clipPlane);
        program.set("uModel", identity);
        program.set("uNormalMatrix", identity.normal(normalMatrix));
        program.set("uTint", 1f, 1f, 1f);
        program.set("uSpecularStrength", 0.25f);
        program.set("uShininess", 24f);
        if (solid != null) solid.draw();
        program.set("uSpecularStrength", 0.02f);
        program.set("uShininess", 4f);
        if (decals != null) decals.draw();
        if (glow != null) {
            // Glowing: brighter than lit, pulsing once a second or so.
            float pulse = (float) (1.25 + 0.2 * Math.sin(frame.time * 4.0));
            program.set("uTint", pulse, pulse, pulse);
            glow.draw();
            program.set("uTint", 1f, 1f, 1f);
        }
        program.set("uSpecularStrength", 0.15f);
        program.set("uShininess", 16f);
        for (int k = 0; k < moving.size(); k++) {
            Mesh m = moving.get(k);
            if (m == null) continue;
            poseMatrix(movers.get(k), clock, pose, model);
            program.set("uModel", model);
            program.set("uNormalMatrix", model.normal(normalMatrix));
            m.draw();
        }
        program.set("uModel", identity);
    }

    /** The minimap shows the elements as they stand (moving ones at the clock's moment). */
    void renderMinimap(FrameContext frame) {
        render(frame);
    }

    /** The still solid elements (bumpers, gates) into the shadow map (the depth shader is in use). */
    void drawDepth(ShaderProgram depthShader) {
        depthShader.set("uModel", identity);
        if (solid != null) solid.draw();
    }

    /** The model matrix of a moving obstacle at a moment of the course clock (its motion's pose). */
    static void poseMatrix(Obstacle.Moving m, double clock, double[] p, Matrix4f out) {
        m.motion().poseAt(clock, p);
        // JOML is column-major: m(column)(row).
        out.set((float) p[0], (float) p[3], (float) p[6], 0f,
                (float) p[1], (float) p[4], (float) p[7], 0f,
                (float) p[2], (float) p[5], (float) p[8], 0f,
                (float) p[9], (float) p[10], (float) p[11], 1f);
    }

    private void free() {
        for (Mesh m : new Mesh[] {solid, decals, glow}) if (m != null) m.close();
        for (Mesh m : moving) if (m != null) m.close();
        moving.clear();
        solid = decals = glow = null;
    }

    @Override
    public void close() {
        free();
        shader.close();
    }
}
