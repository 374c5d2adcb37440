package minigolf.render;

import minigolf.course.Bounds;
import org.joml.Matrix4f;
import org.joml.Vector3f;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL13.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13.glActiveTexture;
import static org.lwjgl.opengl.GL14.GL_DEPTH_COMPONENT24;
import static org.lwjgl.opengl.GL14.GL_TEXTURE_COMPARE_FUNC;
import static org.lwjgl.opengl.GL14.GL_TEXTURE_COMPARE_MODE;
import static org.lwjgl.opengl.GL30.*;

/**
 * The sun's shadow map: a square depth texture rendered with an orthographic camera looking along
 * the sun's rays, fitted once to the course's box (bounds x heights up to the flag's top), so the
 * whole course casts and receives. Sampled with depth comparison (sampler2DShadow, see shadow.glsl).
 */
public final class ShadowMap implements AutoCloseable {
    /** The texture unit the receivers sample the map from. */
    public static final int UNIT = 3;

    private final int size;
    private final int fbo;
    private final int depth;
    private final Matrix4f lightViewProjection = new Matrix4f();
    private final float texelMetres;
    private final float depthRange;
    private int taps = 4;

    /**
     * @param sunDirection unit vector towards the sun
     * @param minZ, maxZ   the lowest and highest points that cast or receive
     */
    public ShadowMap(Bounds b, double minZ, double maxZ, Vector3f sunDirection, int size) {
        this.size = size;
        Vector3f centre = new Vector3f((float) (b.minX() + b.maxX()) / 2, (float) (b.minY() + b.maxY()) / 2,
                (float) (minZ + maxZ) / 2);
        Vector3f up = Math.abs(sunDirection.z) > 0.99f ? new Vector3f(0, 1, 0) : new Vector3f(0, 0, 1);
        Matrix4f view = new Matrix4f().setLookAt(new Vector3f(sunDirection).mul(100).add(centre), centre, up);
        float minX = Float.MAX_VALUE, minY = Float.MAX_VALUE, minD = Float.MAX_VALUE;
        float maxX = -Float.MAX_VALUE, maxY = -Float.MAX_VALUE, maxD = -Float.MAX_VALUE;
        Vector3f p = new Vector3f();
        for (int i = 0; i < 8; i++) {
            p.set((float) ((i & 1) == 0 ? b.minX() : b.maxX()), (float) ((i & 2) == 0 ? b.minY() : b.maxY()),
                    (float) ((i & 4) == 0 ? minZ : maxZ));
            view.transformPosition(p);
            minX = Math.min(minX, p.x);
            maxX = Math.max(maxX, p.x);
            minY = Math.min(minY, p.y);
            maxY = Math.max(maxY, p.y);
            minD = Math.min(minD, -p.z);
            maxD = Math.max(maxD, -p.z);
        }
        float margin = 0.02f * Math.max(maxX - minX, maxY - minY);
        new Matrix4f().setOrtho(minX - margin, maxX + margin, minY - margin, maxY + margin, minD - 1, maxD + 1)
                .mul(view, lightViewProjection);
        texelMetres = (Math.max(maxX - minX, maxY - minY) + 2 * margin) / size;
        depthRange = maxD - minD + 2;

        fbo = glGenFramebuffers();
        depth = glGenTextures();
        int previous = glGetInteger(GL_FRAMEBUFFER_BINDING);
        glBindTexture(GL_TEXTURE_2D, depth);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                (java.nio.ByteBuffer) null);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        int status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glBindFramebuffer(GL_FRAMEBUFFER, previous);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            close();
            throw new RenderException(String.format("The %dx%d shadow map is incomplete: 0x%X", size, size, status));
        }
    }

    public Matrix4f lightViewProjection() {
        return lightViewProjection;
    }

    /** The depth bias receivers subtract (2 mm, in the map's depth units). */
    public float bias() {
        return 0.002f / depthRange;
    }

    /** The map's depths (0 nearest the sun to 1), row by row from the bottom: size x size floats. */
    public float[] readDepth() {
        java.nio.FloatBuffer buffer = org.lwjgl.system.MemoryUtil.memAllocFloat(size * size);
        try {
            glBindTexture(GL_TEXTURE_2D, depth);
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, buffer);
            glBindTexture(GL_TEXTURE_2D, 0);
            float[] out = new float[size * size];
            buffer.get(out);
            return out;
        } finally {
            org.lwjgl.system.MemoryUtil.memFree(buffer);
        }
    }

    /** Depth-compare taps per receiver pixel: 4 (3x3-texel footprint, default) or 1 (2x2). */
    public int taps() {
        return taps;
    }

    public void setTaps(int taps) {
        this.taps = taps == 1 ? 1 : 4;
    }

    public int size() {
        return size;
    }

    /** The width of one texel on the ground, in metres. */
    public float texelMetres() {
        return texelMetres;
    }

    /** Binds the map for drawing depth (cleared) with slope-scaled polygon offset against acne. */
    void begin() {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, size, size);
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 2f);
    }

    void end() {
        glDisable(GL_POLYGON_OFFSET_FILL);
    }

    /** Sets the receiver uniforms of shadow.glsl and binds the map to {@link #UNIT}. */
    void apply(ShaderProgram shader) {
        apply(shader, 1f);
    }

    /** As above, the 4-tap filter's taps {@code softness} times as far apart (a hazier sun's softer edges). */
    void apply(ShaderProgram shader, float softness) {
        glActiveTexture(GL_TEXTURE0 + UNIT);
        glBindTexture(GL_TEXTURE_2D, depth);
        glActiveTexture(GL_TEXTURE0);
        shader.set("uShadowMap", UNIT);
        shader.set("uLightViewProjection", lightViewProjection);
        shader.set("uShadowTexel", softness / size);
        shader.set("uShadowNormalOffset", 1.5f * texelMetres);
        // About two millimetres in depth units ([0, 1] over the light's depth range).
        shader.set("uShadowBias", bias());
    }

    @Override
    public void close() {
        glDeleteFramebuffers(fbo);
        glDeleteTextures(depth);
    }
}
