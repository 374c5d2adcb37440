package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.terrain.Terrain;

import static org.lwjgl.opengl.GL11.*;

/**
 * Still water at z = 0 over the course bounds, drawn after the opaque passes, depth-tested (dry land
 * above 0 hides it) but not writing depth. Each vertex carries the water depth there (max(0, -h)).
 * The shader mixes two render targets owned here, the scene mirrored in z = 0 ({@link #reflection()})
 * and the bed under the surface ({@link #refraction()}), which {@link SceneRenderer} fills first, with
 * an animated du/dv ripple map, Fresnel and depth tint (see water.frag). Nothing is drawn, and no
 * target is allocated, on a course with no point under water.
 */
public final class WaterPass implements RenderPass {
    public static final int MAX_QUADS = 160;
    /** How far the ripples shift the reflected and refracted images, in screen units. */
    public static final float DISTORTION = 0.012f;

    private ShaderProgram shader;
    private Mesh mesh;
    private Texture dudv;
    private final RenderTarget reflection = new RenderTarget();
    private final RenderTarget refraction = new RenderTarget();
    private boolean targetsReady;
    /** The software tier's water (water.frag's BED_BLEND, loaded on first use) and whether it is drawn. */
    private ShaderProgram bedBlendShader;
    private boolean bedBlend;
    /** The wet part of the plane (x, y at z = 0): minX, minY, maxX, maxY; null without water. */
    private float[] wetBox;
    /** The plane's finest grid spacing (metres). */
    private final double minSpacing;

    public WaterPass(Course course, Terrain terrain) {
        this(course, terrain, TerrainMesh.MIN_SPACING);
    }

    /**
     * As above with the plane's grid no finer than {@code minSpacing} metres: the software tier's
     * terrain spacing (0.1 m), so the water's shoreline follows the drawn ground's facets and
     * llvmpipe sets up a quarter of the triangles.
     */
    public WaterPass(Course course, Terrain terrain, double minSpacing) {
        this.minSpacing = minSpacing;
        try {
            rebuild(course, terrain);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * The plane again for changed ground (the editor's brush: ground lowered below zero is water at
     * once). The shader and the ripple texture are loaded the first time there is water and kept.
     */
    public void rebuild(Course course, Terrain terrain) {
        MeshData data = buildPlane(course.bounds(), terrain, minSpacing);
        if (mesh != null) mesh.close();
        mesh = null;
        wetBox = data == null ? null : wetBox(data);
        if (data == null) return;
        if (shader == null) shader = ShaderProgram.load("water");
        if (dudv == null) dudv = Texture.load("water-dudv.png", true);
        mesh = new Mesh(data);
    }
    /** The z = 0 grid with a depth per vertex (layout {3, 1}); null when the terrain never dips below 0. */
    static MeshData buildPlane(Bounds b, Terrain terrain) {
        return buildPlane(b, terrain, TerrainMesh.MIN_SPACING);
    }

    /** As above, the grid no finer than {@code minSpacing} metres. */
    static MeshData buildPlane(Bounds b, Terrain terrain, double minSpacing) {
        double spacing = Math.max(minSpacing, Math.max(b.width(), b.depth()) / MAX_QUADS);
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
                // A quad dry at all four corners has depth 0 throughout, so alpha 0 (see water.frag): leaving it
                // out changes no pixel and spares software rasterisers most of the triangles on a course with a pond.
                if (v[4 * a + 3] == 0 && v[4 * (a + 1) + 3] == 0 && v[4 * c + 3] == 0 && v[4 * (c + 1) + 3] == 0) continue;
                idx[q++] = a;
                idx[q++] = a + 1;
                idx[q++] = c + 1;
                idx[q++] = a;
                idx[q++] = c + 1;
                idx[q++] = c;
            }
        }
        return new MeshData(new int[]{3, 1}, v, java.util.Arrays.copyOf(idx, q));
    }

    /** The x-y box of the plane's drawn (wet) quads. */
    static float[] wetBox(MeshData plane) {
        float[] box = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        float[] v = plane.vertices();
        int stride = plane.stride();
        for (int i : plane.indices()) {
            box[0] = Math.min(box[0], v[i * stride]);
            box[1] = Math.min(box[1], v[i * stride + 1]);
            box[2] = Math.max(box[2], v[i * stride]);
            box[3] = Math.max(box[3], v[i * stride + 1]);
        }
        return box;
    }

    /**
     * The box round everything under the water plane, min x, y, z, max x, y, z: the wet quads' x-y
     * box widened by {@code margin} metres, from far below up to {@code top}. Null without water.
     */
    float[] underwaterBox(float margin, float top) {
        if (wetBox == null) return null;
        return new float[]{wetBox[0] - margin, wetBox[1] - margin, Float.NEGATIVE_INFINITY,
                wetBox[2] + margin, wetBox[3] + margin, top};
    }

    /**
     * Where the water can show in a width x height image seen through {@code viewProjection}: {x, y,
     * width, height} in pixels from the bottom left, widened by {@code margin} of the image's size each
     * way (the ripples shift what the water samples) and clipped to the image; the whole image when a
     * corner is behind the eye; null without water or when it is off screen. The reflection and
     * refraction images are read only there, at each water pixel's own screen position.
     */
    int[] screenRect(org.joml.Matrix4f viewProjection, int width, int height, float margin) {
        if (wetBox == null) return null;
        ScreenBounds screen = new ScreenBounds(viewProjection, width, height);
        for (float x : new float[]{wetBox[0], wetBox[2]}) {
            for (float y : new float[]{wetBox[1], wetBox[3]}) screen.add(x, y, 0);
        }
        return screen.rect(margin * width, margin * height);
    }

    public boolean hasWater() {
        return mesh != null;
    }

    public RenderTarget reflection() {
        return reflection;
    }

    public RenderTarget refraction() {
        return refraction;
    }

    /** Whether the next {@link #render} samples the targets (set by the renderer after it filled them). */
    void useTargets(boolean ready) {
        targetsReady = ready;
    }

    /**
     * Whether the next {@link #render} draws the software tier's water instead (no images: the sky's
     * gradient mirrored, and the bed already drawn behind the water tinted by dual-source blending,
     * fragment colour + destination x a per-pixel factor; only the ripples' shift of the bed is lost).
     */
    void useBedBlend(boolean on) {
        bedBlend = on;
    }

    /** The water without reflections (the minimap). */
    void renderSimple(FrameContext frame) {
        boolean saved = targetsReady, savedBlend = bedBlend;
        targetsReady = false;
        bedBlend = false;
        render(frame);
        targetsReady = saved;
        bedBlend = savedBlend;
    }

    @Override
    public void render(FrameContext frame) {
        if (mesh == null) return;
        glEnable(GL_BLEND);
        ShaderProgram shader = this.shader;
        if (bedBlend) {
            if (bedBlendShader == null) bedBlendShader = ShaderProgram.load("water", "BED_BLEND");
            shader = bedBlendShader;
            glBlendFunc(GL_ONE, org.lwjgl.opengl.GL33.GL_SRC1_COLOR);
        } else {
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        glDepthMask(false);
        shader.use();
        shader.set("uViewProjection", frame.viewProjection);
        Lighting.apply(shader, frame);
        shader.set("uTime", frame.time);
        shader.set("uUseTargets", targetsReady ? 1 : 0);
        shader.set("uDistortion", DISTORTION);
        shader.set("uReflection", 0);
        shader.set("uRefraction", 1);
        shader.set("uDudv", 2);
        if (targetsReady && !bedBlend) {
            reflection.bindColour(0);
            refraction.bindColour(1);
        }
        dudv.bind(2);
        mesh.draw();
        org.lwjgl.opengl.GL13.glActiveTexture(org.lwjgl.opengl.GL13.GL_TEXTURE0);
        glDepthMask(true);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDisable(GL_BLEND);
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        if (shader != null) shader.close();
        if (bedBlendShader != null) bedBlendShader.close();
        if (dudv != null) dudv.close();
        reflection.close();
        refraction.close();
    }
}
