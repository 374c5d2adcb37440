package minigolf.app;

import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import minigolf.course.CourseException;
import minigolf.physics.World;
import minigolf.render.Framebuffer;
import minigolf.render.OrbitCamera;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL12.GL_CLAMP_TO_EDGE;
import static org.lwjgl.system.MemoryUtil.memAlloc;
import static org.lwjgl.system.MemoryUtil.memFree;

/**
 * Course previews for the course list, rendered off-screen with the game's own renderer into a
 * framebuffer and copied, top row first, into textures the interface draws. One per frame, so the menu stays responsive.
 * A course that fails to load gets no texture (id -1 is remembered so it is not retried).
 */
final class Thumbnails implements AutoCloseable {
    private final Map<Path, Integer> textures = new HashMap<>();

    int texture(Path course) {
        Integer t = textures.get(course);
        return t == null || t < 0 ? 0 : t;
    }

    /** Renders the first course without a preview; leaves the default framebuffer bound. */
    void renderNext(List<CourseFolders.CourseEntry> courses, int width, int height) {
        for (CourseFolders.CourseEntry c : courses) {
            if (textures.containsKey(c.file())) continue;
            textures.put(c.file(), render(c.file(), width, height));
            return;
        }
    }

    private static int render(Path file, int width, int height) {
        World world;
        try {
            world = World.load(file);
        } catch (CourseException e) {
            return -1;
        }
        ByteBuffer pixels = memAlloc(width * height * 4);
        try (SceneRenderer renderer = new SceneRenderer(world.course(), world.terrain(), TerrainMesh.ColorMode.GREEN);
             Framebuffer target = new Framebuffer(width, height, 0)) {
            OrbitCamera cam = OrbitCamera.behindBall(world.course(), world.terrain(), (float) width / height);
            target.bind();
            renderer.render(cam, width, height, 0f);
            target.resolve();
            target.readPixels(pixels);
            flipRows(pixels, width * 4, height); // GL reads bottom-up; Nuklear maps an image's top to v = 0
            int tex = glGenTextures();
            glBindTexture(GL_TEXTURE_2D, tex);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
            glBindTexture(GL_TEXTURE_2D, 0);
            return tex;
        } catch (RuntimeException e) {
            return -1;
        } finally {
            memFree(pixels);
            org.lwjgl.opengl.GL30.glBindFramebuffer(org.lwjgl.opengl.GL30.GL_FRAMEBUFFER, 0);
        }
    }

    private static void flipRows(ByteBuffer pixels, int stride, int rows) {
        byte[] a = new byte[stride], b = new byte[stride];
        for (int top = 0, bottom = rows - 1; top < bottom; top++, bottom--) {
            pixels.get(top * stride, a);
            pixels.get(bottom * stride, b);
            pixels.put(top * stride, b);
            pixels.put(bottom * stride, a);
        }
    }

    @Override
    public void close() {
        for (int t : textures.values()) if (t > 0) glDeleteTextures(t);
        textures.clear();
    }
}
