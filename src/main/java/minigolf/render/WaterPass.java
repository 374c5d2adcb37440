package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.terrain.Terrain;

import static org.lwjgl.opengl.GL11.*;

/**
 * Still water: a flat translucent plane at z = 0 over the course bounds, drawn after the opaque
 * passes with blending, depth-tested (dry land above 0 hides it) but not writing depth. Each vertex
 * carries the water depth there (max(0, -h)) so that deep water is darker and more opaque and the
 * shoreline fades out; a Fresnel term mixes in the sky at grazing angles. Nothing is drawn on a
 * course with no point under water.
 */
public final class WaterPass implements RenderPass {
    public static final int MAX_QUADS = 160;

    private final ShaderProgram shader;
    private final Mesh mesh;

    public WaterPass(Course course, Terrain terrain) {
        MeshData data = buildPlane(course.bounds(), terrain);
        if (data == null) {
            shader = null;
            mesh = null;
        } else {
            shader = ShaderProgram.load("water");
            mesh = new Mesh(data);
        }
    }

    /** The z = 0 grid with a depth per vertex (layout {3, 1}); null when the terrain never dips below 0. */
    static MeshData buildPlane(Bounds b, Terrain terrain) {
        double spacing = Math.max(TerrainMesh.MIN_SPACING, Math.max(b.width(), b.depth()) / MAX_QUADS);
        int nx = Math.max(1, Math.min(MAX_QUADS, (int) Math.ceil(b.width() / spacing - 1e-9)));
        int ny = Math.max(1, Math.min(MAX_QUADS, (int) Math.ceil(b.depth() / spacing - 1e-9)));
        int cols = nx + 1, rows = ny + 1;
        float[] v = new float[cols * rows * 4];
        boolean wet = false;
        int p = 0;
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) {
                double x = b.minX() + b.width() * i / nx, y = b.minY() + b.depth() * j / ny;
                double depth = Math.max(0, -terrain.height(x, y));
                wet |= depth > 0;
                v[p++] = (float) x;
                v[p++] = (float) y;
                v[p++] = 0f;
                v[p++] = (float) depth;
            }
        }
        if (!wet) return null;
        int[] idx = new int[nx * ny * 6];
        int q = 0;
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                int a = j * cols + i, c = a + cols;
                idx[q++] = a;
                idx[q++] = a + 1;
                idx[q++] = c + 1;
                idx[q++] = a;
                idx[q++] = c + 1;
                idx[q++] = c;
            }
        }
        return new MeshData(new int[]{3, 1}, v, idx);
    }

    public boolean hasWater() {
        return mesh != null;
    }

    /** The water without reflections (the minimap). */
    void renderSimple(FrameContext frame) {
        render(frame);
    }

    @Override
    public void render(FrameContext frame) {
        if (mesh == null) return;
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(false);
        shader.use();
        shader.set("uViewProjection", frame.viewProjection);
        Lighting.apply(shader, frame);
        shader.set("uTime", frame.time);
        mesh.draw();
        glDepthMask(true);
        glDisable(GL_BLEND);
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        if (shader != null) shader.close();
    }
}
