package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;

/**
 * What every pass needs for one frame: the camera matrices and eye, the sun, the viewport. Built
 * once per frame by {@link SceneRenderer} and handed to the passes in order. Later passes (shadows,
 * reflections) can add their products here.
 */
public final class FrameContext {
    public final Matrix4f view = new Matrix4f();
    public final Matrix4f projection = new Matrix4f();
    public final Matrix4f viewProjection = new Matrix4f();
    public final Matrix4f inverseViewProjection = new Matrix4f();
    public final Vector3f eye = new Vector3f();
    public final Sun sun;
    /** The world's sky and air (fog, sky gradient, clouds); Meadowbrook's unless set. */
    public Atmosphere atmosphere = Atmosphere.of(minigolf.theme.Themes.MEADOWBROOK);
    /** The materials' textures (materials.glsl), or null where a pass is drawn without a scene (tests). */
    MaterialTextures materials;
    public int viewportWidth;
    public int viewportHeight;
    /** Geometry with dot(clipPlane, (world, 1)) < 0 is cut away (GL_CLIP_DISTANCE0 on); (0,0,0,1) keeps all. */
    public final Vector4f clipPlane = new Vector4f(0, 0, 0, 1);
    /** The sun's shadow map that receivers sample (null: no shadow uniforms are set), and whether to use it. */
    public ShadowMap shadowMap;
    public boolean shadowsOn;
    /**
     * Whether lit shaders compute the balls' shadows themselves (true), or leave them to a second,
     * scissored draw of the surfaces round the balls (false; {@link SceneRenderer} on software
     * rasterisers, where the per-pixel ball loop cost every pixel of the screen).
     */
    public boolean ballShadowsInline = true;
    /** The balls' analytic shadows (shadow.glsl): centre x, y, z and radius per ball, the first {@code ballShadowCount}. */
    public final float[] ballShadows = new float[4 * MAX_BALL_SHADOWS];
    public int ballShadowCount;
    /** As MAX_BALL_SHADOWS in shadow.glsl; further balls cast no shadow. */
    public static final int MAX_BALL_SHADOWS = 8;
    /** Seconds since the renderer started; 0 in screenshots (deterministic frames). */
    public float time;

    public FrameContext(Sun sun) {
        this.sun = sun;
    }

    /** Fills the camera part for a viewport of width x height pixels. */
    public FrameContext update(OrbitCamera camera, int width, int height, float time) {
        viewportWidth = width;
        viewportHeight = height;
        float aspect = (float) width / Math.max(1, height);
        camera.view(view);
        camera.projection(aspect, projection);
        projection.mul(view, viewProjection);
        viewProjection.invert(inverseViewProjection);
        eye.set(camera.eye());
        this.time = time;
        return this;
    }

    /**
     * This frame seen in the mirror z = 0: view * diag(1, 1, -1), eye below the water. A point on the
     * water lands on the same pixel in both, so the water samples the reflection at its own pixel.
     */
    public FrameContext mirrorOf(FrameContext src, int width, int height) {
        viewportWidth = width;
        viewportHeight = height;
        src.view.scale(1, 1, -1, view);
        projection.set(src.projection);
        projection.mul(view, viewProjection);
        viewProjection.invert(inverseViewProjection);
        eye.set(src.eye.x, src.eye.y, -src.eye.z);
        return sharedStateOf(src);
    }

    /** Copies the camera of {@code src} for a width x height target (the refraction). */
    public FrameContext copyOf(FrameContext src, int width, int height) {
        viewportWidth = width;
        viewportHeight = height;
        view.set(src.view);
        projection.set(src.projection);
        viewProjection.set(src.viewProjection);
        inverseViewProjection.set(src.inverseViewProjection);
        eye.set(src.eye);
        return sharedStateOf(src);
    }

    /**
     * What a water target's frame takes over from the scene's besides the camera: time, shadows and
     * balls. Its own draws compute the balls' shadows inline (no second, scissored draw there).
     */
    private FrameContext sharedStateOf(FrameContext src) {
        time = src.time;
        atmosphere = src.atmosphere;
        materials = src.materials;
        shadowMap = src.shadowMap;
        shadowsOn = src.shadowsOn;
        ballShadowsInline = true;
        System.arraycopy(src.ballShadows, 0, ballShadows, 0, ballShadows.length);
        ballShadowCount = src.ballShadowCount;
        return this;
    }

    /**
     * A straight-down orthographic view of the rectangle [minX, maxX] x [minY, maxY] (x right, y up
     * on screen) for a width x height viewport: the minimap. The rectangle is padded to the viewport's
     * aspect ratio; heights between {@code minZ} and {@code maxZ} are in the depth range.
     */
    public FrameContext updateTopDown(double minX, double minY, double maxX, double maxY, double minZ, double maxZ,
                                      int width, int height, float time) {
        viewportWidth = width;
        viewportHeight = height;
        float cx = (float) (minX + maxX) / 2, cy = (float) (minY + maxY) / 2;
        float halfW = (float) (maxX - minX) / 2, halfH = (float) (maxY - minY) / 2;
        float aspect = (float) width / Math.max(1, height);
        if (halfW / halfH < aspect) halfW = halfH * aspect;
        else halfH = halfW / aspect;
        float top = (float) maxZ + 5;
        eye.set(cx, cy, top);
        view.setLookAt(cx, cy, top, cx, cy, 0, 0, 1, 0);
        projection.setOrtho(-halfW, halfW, -halfH, halfH, 0.01f, (float) (top - minZ) + 1);
        projection.mul(view, viewProjection);
        viewProjection.invert(inverseViewProjection);
        this.time = time;
        return this;
    }

    /**
     * One directional light. {@code direction} points from the ground towards the sun (unit length);
     * {@code shadowSoftness} widens the shadow filter's footprint (1: 3x3 texels).
     */
    public record Sun(Vector3f direction, Vector3f color, Vector3f skyAmbient, Vector3f groundAmbient,
                      float shadowSoftness) {
        public Sun(Vector3f direction, Vector3f color, Vector3f skyAmbient, Vector3f groundAmbient) {
            this(direction, color, skyAmbient, groundAmbient, 1f);
        }

        /** Meadowbrook's afternoon sun. */
        public static Sun afternoon() {
            return new Sun(new Vector3f(-0.45f, -0.55f, 0.70f).normalize(), new Vector3f(1.0f, 0.96f, 0.88f),
                    new Vector3f(0.40f, 0.46f, 0.56f), new Vector3f(0.24f, 0.22f, 0.16f));
        }

        /** A world's sun (Meadowbrook's is {@link #afternoon()}, to the rounding of its angles). */
        public static Sun of(minigolf.theme.Theme.Light light) {
            double[] d = light.direction();
            return new Sun(new Vector3f((float) d[0], (float) d[1], (float) d[2]).normalize(), Atmosphere.v(light.sun()),
                    Atmosphere.v(light.skyAmbient()), Atmosphere.v(light.groundAmbient()), (float) light.shadowSoftness());
        }
    }
}
