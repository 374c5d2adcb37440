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
    /** The programs per cell group: bit 0 clouds, bit 1 the sun's disc, bit 2 ground without per-pixel sea. */
    private ShaderProgram[] programs;
    /** Whether cells off the seaside's shore are drawn without the per-pixel sea (software tier). */
    private boolean shoreSplit;
    private final float[] groundX = new float[(GRID_X + 1) * (GRID_Y + 1)];
    private final float[] groundY = new float[(GRID_X + 1) * (GRID_Y + 1)];
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
    /** The shore's band for sorting the cells (software tier by the sea, once a ground is set), or null: built with the ground, not per frame. */
    private Shore shore;
    private int[] lastCounts = new int[8];

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
        // Where the ground shows no per-pixel detail (software rasterisers), the cells off the shore's
        // band take their colour from the grid's corners (groups 4 and 6; see sortCells), and the band's
        // cells draw the shore with cheaper arithmetic (sky.frag's SIMPLE_SHORE).
        shoreSplit = sea != null && groundLayer < 0;
        programs = programs(shoreSplit);
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

    /** The programs per cell group (see {@link #programs}); {@code simpleShore}: the band's cells with SIMPLE_SHORE. */
    private ShaderProgram[] programs(boolean simpleShore) {
        String s = sea != null ? "SEA" : "NO_SEA";
        // Per pixel (the shoreline, the ground's detail) only in the cells wholly below the horizon.
        String p = sea != null ? "SEA_PIXEL" : "NO_SEA_PIXEL";
        String g = groundLayer >= 0 ? "GROUND_DETAIL" : "NO_GROUND_DETAIL";
        String simple = simpleShore ? "SIMPLE_SHORE" : "NO_SIMPLE_SHORE";
        boolean split = sea != null && groundLayer < 0;
        return new ShaderProgram[]{ShaderProgram.load("sky", s, p, g, simple), ShaderProgram.load("sky", "CLOUDS", s),
                ShaderProgram.load("sky", "SUN_DISC", s, p, g, simple), ShaderProgram.load("sky", "CLOUDS", "SUN_DISC", s),
                split ? ShaderProgram.load("sky", s, "NO_SEA_PIXEL", g) : null, null,
                split ? ShaderProgram.load("sky", "SUN_DISC", s, "NO_SEA_PIXEL", g) : null, null};
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
        return sortCells(inverseViewProjection, toSun, cornerUp, cornerSun, order, near, far, null, null, null);
    }

    /**
     * As above, and with a {@code shore} (software rasterisers by the sea), bit 2 set on the cells
     * below the horizon that cannot show the shore's band ({@link ShoreCells}): their grid corners
     * give their colour, no per-pixel sea. {@code groundX}/{@code groundY}: scratch, one per corner.
     */
    static int[] sortCells(Matrix4f inverseViewProjection, org.joml.Vector3f toSun, float[] cornerUp, float[] cornerSun,
                           int[] order, Vector4f near, Vector4f far, Shore shore, float[] groundX, float[] groundY) {
        for (int j = 0; j <= GRID_Y; j++) {
            for (int i = 0; i <= GRID_X; i++) {
                inverseViewProjection.transform(near.set(ndcX(i), ndcY(j), -1f, 1f));
                inverseViewProjection.transform(far.set(ndcX(i), ndcY(j), 1f, 1f));
                float nx = near.x / near.w, ny = near.y / near.w, nz = near.z / near.w;
                float dx = far.x / far.w - nx, dy = far.y / far.w - ny, dz = far.z / far.w - nz;
                float len = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
                int c = j * (GRID_X + 1) + i;
                cornerUp[c] = dz / len;
                cornerSun[c] = (dx * toSun.x + dy * toSun.y + dz * toSun.z) / (len * toSun.length());
                if (shore != null) {
                    // Where the corner's ray meets the ground plane (as sky.vert: from the near point); NaN: it does not.
                    boolean hits = dz < 0 && nz > shore.level();
                    float t = hits ? (shore.level() - nz) / dz : Float.NaN;
                    groundX[c] = nx + dx * t;
                    groundY[c] = ny + dy * t;
                }
            }
        }
        int[] group = new int[GRID_X * GRID_Y];
        int[] counts = new int[8];
        float[] qx = new float[4], qy = new float[4];
        for (int j = 0; j < GRID_Y; j++) {
            for (int i = 0; i < GRID_X; i++) {
                int a = j * (GRID_X + 1) + i, b = a + 1, c = a + GRID_X + 1, d = c + 1;
                boolean sky = cornerUp[a] > 0 || cornerUp[b] > 0 || cornerUp[c] > 0 || cornerUp[d] > 0;
                boolean sun = Math.max(Math.max(cornerSun[a], cornerSun[b]), Math.max(cornerSun[c], cornerSun[d])) > SUN_CELL_COS;
                int g = (sky ? 1 : 0) | (sun ? 2 : 0);
                if (shore != null && !sky && plainGround(shore, groundX, groundY, qx, qy, a, b, d, c)) g |= 4;
                group[j * GRID_X + i] = g;
                counts[g] += 6;
            }
        }
        int[] next = new int[counts.length];
        for (int g = 1; g < counts.length; g++) next[g] = next[g - 1] + counts[g - 1];
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

    /** Whether the cell with these corners (in order round it) lies on the ground, wholly off the shore's band. */
    private static boolean plainGround(Shore shore, float[] groundX, float[] groundY, float[] qx, float[] qy, int... corners) {
        for (int k = 0; k < 4; k++) {
            qx[k] = groundX[corners[k]];
            qy[k] = groundY[corners[k]];
            if (Float.isNaN(qx[k]) || Float.isNaN(qy[k])) return false;
        }
        return ShoreCells.outsideBand(qx, qy, shore.courseRect(), shore.inner(), shore.outer());
    }

    /**
     * The seaside's shore for {@link #sortCells}: the ground plane's height, the course's rectangle,
     * and the band of distances from it where sky.frag's sea differs from its grid corners' colour
     * (grass blends into beach from inner on; the foam reaches to outer).
     */
    record Shore(float level, float[] courseRect, float inner, float outer) {
        static Shore of(Sea sea, float level) {
            return new Shore(level, sea.courseRect(), sea.shore() - BEACH_WIDTH, sea.shore() + FOAM_REACH);
        }
    }

    /** sky.frag's beach: grass gives way to sand from this far inside the shore. */
    static final float BEACH_WIDTH = 2.7f;
    /** sky.frag's foam: its line (0.25 m out, swinging 0.15 m, 0.22 m wide) is below 1e-5 of its strength beyond this. */
    static final float FOAM_REACH = 1.2f;

    @Override
    public void render(FrameContext frame) {
        int[] counts = sortCells(frame.inverseViewProjection, frame.sun.direction(), cornerUp, cornerSun, order, near, far,
                shore, groundX, groundY);
        lastCounts = counts;
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
        this.shore = shoreSplit && !Float.isNaN(groundLevel) ? Shore.of(sea, groundLevel) : null;
        this.groundColor = color.clone();
        this.fadeStart = fadeStart;
        this.fadeEnd = fadeEnd;
    }

    /** The shore the cells are sorted by (null: no split; tests). */
    Shore shore() {
        return shore;
    }

    /** The indices drawn per cell group in the last frame (see {@link #sortCells}; tests). */
    int[] lastCounts() {
        return lastCounts.clone();
    }

    /**
     * Off: every ground cell by the sea gets the per-pixel shore, as before the split (tests compare
     * the pictures); on: the software tier's split again. Only where the split can exist.
     */
    void splitShore(boolean on) {
        if (sea == null || groundLayer >= 0 || programs[4] == null) return;
        shoreSplit = on;
        shore = on && !Float.isNaN(groundLevel) ? Shore.of(sea, groundLevel) : null;
    }

    /**
     * Off: the shore's band with the high tier's arithmetic (exp, sin, the fade per pixel), as before
     * SIMPLE_SHORE (tests compare the pictures); on: the software tier's again. Only where the split can exist.
     */
    void simpleShore(boolean on) {
        if (sea == null || groundLayer >= 0) return;
        programs = programs(on);
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
        for (ShaderProgram p : programs) if (p != null) p.close();
        clouds.close();
        MemoryUtil.memFree(indices);
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        glDeleteBuffers(ebo);
    }
}
