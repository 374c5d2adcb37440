package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;
import org.lwjgl.system.MemoryUtil;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL15.*;
import static org.lwjgl.opengl.GL20.*;
import static org.lwjgl.opengl.GL30.*;

/**
 * The procedural sky dome (gradient, sun, drifting clouds; see sky.vert): a grid over the screen at
 * the far plane, no depth writes, drawn after the opaque passes. The sky is computed at the grid's
 * corners and interpolated, and only the cells that can show a cloud (some corner above the horizon)
 * read the cloud texture per pixel, only those near the sun draw its disc: from the usual view down
 * onto a course neither shows, so a software rasteriser shades most of the sky for its gradient alone.
 * Below the horizon it can show the meadow round the course ({@link #setGround}), computed the same way.
 */
public final class SkyPass implements RenderPass {
    /** The cloud tile's texels per side (4 texels per cell of the finest octave). */
    static final int CLOUD_TEXTURE_SIZE = 512;
    /** Grid cells across and up the screen: about 80 pixels each at 1280x720. */
    static final int GRID_X = 16, GRID_Y = 10;
    /** Cells whose corners all point further than this from the sun cannot hold its disc (cells span about 3.5 degrees). */
    static final double SUN_CELL_COS = Math.cos(Math.toRadians(12));
    /** The programs per cell group: bit 0 clouds, bit 1 the sun's disc. */
    private final ShaderProgram[] programs;
    private final Texture clouds = Texture.fromPixels(CLOUD_TEXTURE_SIZE, CLOUD_TEXTURE_SIZE,
            CloudNoise.rgba(CLOUD_TEXTURE_SIZE), true);
    private final int vao = glGenVertexArrays();
    private final int vbo = glGenBuffers();
    private final int ebo = glGenBuffers();
    private final int[] order = new int[GRID_X * GRID_Y * 6];
    private final IntBuffer indices = MemoryUtil.memAllocInt(order.length);
    private final float[] cornerUp = new float[(GRID_X + 1) * (GRID_Y + 1)];
    private final float[] cornerSun = new float[(GRID_X + 1) * (GRID_Y + 1)];
    private final Vector4f near = new Vector4f(), far = new Vector4f();
    /** The meadow's plane below the horizon (NaN: none, the hazy far distance), its colour and fade. */
    private float groundLevel = Float.NaN;
    private float[] groundColor = {0, 0, 0};
    private float fadeStart, fadeEnd;

    /** The shore (metres from the course's bounds), the course's bounds, the sea's and the beach's colours: a seaside world. */
    record Sea(float shore, float[] courseRect, float[] seaColor, float[] beachColor) {
    }

    private final Sea sea;
    /** The texture-array layer the ground shows (MaterialPatterns.Layer), or -1 for a plain colour. */
    private final int groundLayer;

    public SkyPass() {
        this(null, -1);
    }

    /**
     * A sky whose ground ends at a beach with the sea beyond (null: ground to the horizon), the ground
     * showing the material of {@code groundLayer} per pixel (-1: a plain colour). Only the cells wholly
     * below the horizon get the ground's detail: those with some corner above it lie far away, where
     * the detail has faded anyway.
     */
    SkyPass(Sea sea, int groundLayer) {
        this.sea = sea;
        this.groundLayer = groundLayer;
        String s = sea != null ? "SEA" : "NO_SEA";
        // Per pixel (the shoreline, the ground's detail) only in the cells wholly below the horizon.
        String p = sea != null ? "SEA_PIXEL" : "NO_SEA_PIXEL";
        String g = groundLayer >= 0 ? "GROUND_DETAIL" : "NO_GROUND_DETAIL";
        programs = new ShaderProgram[]{ShaderProgram.load("sky", s, p, g), ShaderProgram.load("sky", "CLOUDS", s),
                ShaderProgram.load("sky", "SUN_DISC", s, p, g), ShaderProgram.load("sky", "CLOUDS", "SUN_DISC", s)};
        glBindVertexArray(vao);
        FloatBuffer corners = MemoryUtil.memAllocFloat((GRID_X + 1) * (GRID_Y + 1) * 2);
        try {
            for (int j = 0; j <= GRID_Y; j++) {
                for (int i = 0; i <= GRID_X; i++) corners.put(ndcX(i)).put(ndcY(j));
            }
            corners.flip();
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, corners, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(corners);
        }
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, (long) order.length * Integer.BYTES, GL_DYNAMIC_DRAW);
        glVertexAttribPointer(0, 2, GL_FLOAT, false, 0, 0L);
        glEnableVertexAttribArray(0);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    private static float ndcX(int i) {
        return 2f * i / GRID_X - 1f;
    }

    private static float ndcY(int j) {
        return 2f * j / GRID_Y - 1f;
    }

    /**
     * Sorts the grid's triangles into {@link #order} by cell group and returns each group's number of
     * indices, groups in order: bit 0 set when some corner is above the horizon (clouds may show; the
     * horizon is a straight line on the screen, so a cell whose four corners are below it lies wholly
     * below it), bit 1 when some corner points within 12 degrees of the sun (its disc may show).
     */
    static int[] sortCells(Matrix4f inverseViewProjection, org.joml.Vector3f toSun, float[] cornerUp, float[] cornerSun,
                           int[] order, Vector4f near, Vector4f far) {
        for (int j = 0; j <= GRID_Y; j++) {
            for (int i = 0; i <= GRID_X; i++) {
                inverseViewProjection.transform(near.set(ndcX(i), ndcY(j), -1f, 1f));
                inverseViewProjection.transform(far.set(ndcX(i), ndcY(j), 1f, 1f));
                float dx = far.x / far.w - near.x / near.w, dy = far.y / far.w - near.y / near.w, dz = far.z / far.w - near.z / near.w;
                float len = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
                cornerUp[j * (GRID_X + 1) + i] = dz / len;
                cornerSun[j * (GRID_X + 1) + i] = (dx * toSun.x + dy * toSun.y + dz * toSun.z) / (len * toSun.length());
            }
        }
        int[] group = new int[GRID_X * GRID_Y];
        int[] counts = new int[4];
        for (int j = 0; j < GRID_Y; j++) {
            for (int i = 0; i < GRID_X; i++) {
                int a = j * (GRID_X + 1) + i, b = a + 1, c = a + GRID_X + 1, d = c + 1;
                boolean sky = cornerUp[a] > 0 || cornerUp[b] > 0 || cornerUp[c] > 0 || cornerUp[d] > 0;
                boolean sun = Math.max(Math.max(cornerSun[a], cornerSun[b]), Math.max(cornerSun[c], cornerSun[d])) > SUN_CELL_COS;
                int g = (sky ? 1 : 0) | (sun ? 2 : 0);
                group[j * GRID_X + i] = g;
                counts[g] += 6;
            }
        }
        int[] next = {0, counts[0], counts[0] + counts[1], counts[0] + counts[1] + counts[2]};
        for (int j = 0; j < GRID_Y; j++) {
            for (int i = 0; i < GRID_X; i++) {
                int a = j * (GRID_X + 1) + i, b = a + 1, c = a + GRID_X + 1, d = c + 1;
                int k = next[group[j * GRID_X + i]];
                order[k] = a;
                order[k + 1] = b;
                order[k + 2] = d;
                order[k + 3] = a;
                order[k + 4] = d;
                order[k + 5] = c;
                next[group[j * GRID_X + i]] += 6;
            }
        }
        return counts;
    }

    @Override
    public void render(FrameContext frame) {
        int[] counts = sortCells(frame.inverseViewProjection, frame.sun.direction(), cornerUp, cornerSun, order, near, far);
        glBindVertexArray(vao);
        indices.clear();
        indices.put(order).flip();
        glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, indices);
        // Drawn after the opaque passes: at depth 1 (the far plane) with GL_LEQUAL it fills only the
        // pixels nothing covered (early depth test).
        glDepthMask(false);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        clouds.bind(0);
        long first = 0;
        for (int g = 0; g < programs.length; g++) {
            if (counts[g] > 0) {
                use(programs[g], frame);
                glDrawElements(GL_TRIANGLES, counts[g], GL_UNSIGNED_INT, first * Integer.BYTES);
            }
            first += counts[g];
        }
        glBindVertexArray(0);
        glDepthMask(true);
    }

    /**
     * Shows a flat meadow of {@code color} at height {@code level} below the horizon (lit by the sun,
     * hazed as the terrain), fading over fadeStart to fadeEnd metres of horizontal distance from the
     * eye into the sky's colours: see {@link SurroundingsPass}.
     */
    public void setGround(double level, float[] color, float fadeStart, float fadeEnd) {
        this.groundLevel = (float) level;
        this.groundColor = color.clone();
        this.fadeStart = fadeStart;
        this.fadeEnd = fadeEnd;
    }

    private void use(ShaderProgram shader, FrameContext frame) {
        shader.use();
        Lighting.apply(shader, frame);
        boolean ground = !Float.isNaN(groundLevel);
        shader.set("uGround", ground ? groundLevel : 0f, ground ? 1f : 0f);
        shader.set("uGroundColor", groundColor[0], groundColor[1], groundColor[2]);
        shader.set("uFade", fadeStart, fadeEnd);
        shader.set("uInverseViewProjection", frame.inverseViewProjection);
        shader.set("uSunDirection", frame.sun.direction());
        shader.set("uTime", frame.time);
        shader.set("uClouds", 0);
        shader.set("uCloudPeriod", (float) CloudNoise.PERIOD);
        shader.set("uCloudTexels", (float) CLOUD_TEXTURE_SIZE);
        shader.set("uCloudCover", frame.atmosphere.cloudCover());
        shader.set("uGroundLayer", (float) groundLayer);
        if (sea != null) {
            shader.set("uShore", sea.shore());
            float[] r = sea.courseRect();
            shader.set("uCourseRect", r[0], r[1], r[2], r[3]);
            shader.set("uSeaColor", sea.seaColor()[0], sea.seaColor()[1], sea.seaColor()[2]);
            shader.set("uBeachColor", sea.beachColor()[0], sea.beachColor()[1], sea.beachColor()[2]);
        }
        shader.set("uCloudLit", frame.atmosphere.cloudLit());
        shader.set("uCloudShade", frame.atmosphere.cloudShade());
        glUniform2f(shader.location("uGridStep"), 2f / GRID_X, 2f / GRID_Y);
        shader.set("uGridPixels", (float) frame.viewportWidth / GRID_X);
    }

    @Override
    public void close() {
        for (ShaderProgram p : programs) p.close();
        clouds.close();
        MemoryUtil.memFree(indices);
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        glDeleteBuffers(ebo);
    }
}
