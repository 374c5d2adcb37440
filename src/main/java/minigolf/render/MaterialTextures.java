package minigolf.render;

import minigolf.texture.MaterialPatterns;
import minigolf.theme.Theme;

import java.nio.ByteBuffer;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_CLAMP_TO_EDGE;
import static org.lwjgl.opengl.GL12.glTexImage3D;
import static org.lwjgl.opengl.GL13.GL_TEXTURE0;
import static org.lwjgl.opengl.GL13.glActiveTexture;
import static org.lwjgl.opengl.GL30.*;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/**
 * The materials' detail ({@link MaterialPatterns}: grass, sand, wood, stone, rock, snow) as one
 * mipmapped, tiling texture array on {@link #UNIT}, made once per renderer, and the course's ground
 * occlusion ({@link OcclusionMap}) on {@link #OCCLUSION_UNIT}. {@code materials.glsl} reads both.
 */
final class MaterialTextures implements AutoCloseable {
    static final int UNIT = 5;
    static final int OCCLUSION_UNIT = 6;
    /** Texels per side of each layer. */
    static final int SIZE = 256;
    /** The patterns are the same for every renderer: made once per process. */
    private static byte[] patterns;

    private final int array;
    private int occlusion;
    private float[] occlusionRect = {0, 0, 1, 1};
    private final float edgeLayer, sandLayer;

    /** The textures for a world (which layers its course edge and its rough zones show). */
    MaterialTextures(Theme theme) {
        edgeLayer = edgeLayer(theme.materials().edge());
        sandLayer = (theme.scenery().ground() == Theme.Ground.SNOW ? MaterialPatterns.Layer.SNOW : MaterialPatterns.Layer.SAND).ordinal();
        byte[] all = patterns();
        int layers = MaterialPatterns.Layer.values().length;
        ByteBuffer pixels = memAlloc(all.length);
        try {
            pixels.put(all).flip();
            array = glGenTextures();
            glBindTexture(GL_TEXTURE_2D_ARRAY, array);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, SIZE, SIZE, layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        } finally {
            memFree(pixels);
        }
    }

    private static synchronized byte[] patterns() {
        if (patterns == null) patterns = MaterialPatterns.all(SIZE);
        return patterns;
    }

    /** Replaces the ground occlusion map (after the obstacles changed). */
    void setOcclusion(OcclusionMap map) {
        if (occlusion == 0) occlusion = glGenTextures();
        byte[] b = map.bytes();
        ByteBuffer pixels = memAlloc(b.length);
        try {
            pixels.put(b).flip();
            glBindTexture(GL_TEXTURE_2D, occlusion);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, map.width(), map.height(), 0, GL_RED, GL_UNSIGNED_BYTE, pixels);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glBindTexture(GL_TEXTURE_2D, 0);
        } finally {
            memFree(pixels);
        }
        var bb = map.bounds();
        occlusionRect = new float[]{(float) bb.minX(), (float) bb.minY(), (float) (1 / bb.width()), (float) (1 / bb.depth())};
    }

    /** Binds both textures and sets materials.glsl's uniforms (programs without them ignore them). */
    void apply(ShaderProgram shader) {
        glActiveTexture(GL_TEXTURE0 + UNIT);
        glBindTexture(GL_TEXTURE_2D_ARRAY, array);
        glActiveTexture(GL_TEXTURE0 + OCCLUSION_UNIT);
        glBindTexture(GL_TEXTURE_2D, occlusion);
        glActiveTexture(GL_TEXTURE0);
        shader.set("uMaterials", UNIT);
        shader.set("uOcclusion", OCCLUSION_UNIT);
        shader.set("uOcclusionRect", occlusionRect[0], occlusionRect[1], occlusionRect[2], occlusionRect[3]);
        shader.set("uEdgeLayer", edgeLayer);
        shader.set("uSandLayer", sandLayer);
    }

    /** The layer the ground round the course shows: snow in a winter world, sand in a desert, else grass. */
    static int groundLayer(Theme theme) {
        return (switch (theme.scenery().ground()) {
            case GRASS -> MaterialPatterns.Layer.GRASS;
            case SAND -> MaterialPatterns.Layer.SAND;
            case SNOW -> MaterialPatterns.Layer.SNOW;
        }).ordinal();
    }

    /** The texture-array layer a world's course edge is drawn with. */
    static int edgeLayer(Theme.EdgeMaterial edge) {
        return switch (edge) {
            case STONE_WALL -> MaterialPatterns.Layer.STONE.ordinal();
            case SOIL, ROCK, SANDSTONE, SNOWY_ROCK -> MaterialPatterns.Layer.ROCK.ordinal();
        };
    }

    @Override
    public void close() {
        glDeleteTextures(array);
        if (occlusion != 0) glDeleteTextures(occlusion);
    }
}
