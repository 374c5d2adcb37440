package minigolf.render;

import minigolf.course.Course;
import minigolf.terrain.Terrain;
import org.joml.Vector3f;

import java.util.List;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL13.GL_MULTISAMPLE;

/**
 * Draws a course: sky, terrain, objects, then water (translucent, last). Owns the passes; needs a
 * current GL context from construction to {@link #close()}.
 */
public final class SceneRenderer implements AutoCloseable {
    private final SkyPass sky;
    private final TerrainPass terrain;
    private final ObjectsPass objects;
    private final WaterPass water;
    private final List<RenderPass> passes;
    private final FrameContext frame = new FrameContext(FrameContext.Sun.afternoon());

    public SceneRenderer(Course course, Terrain surface, TerrainMesh.ColorMode mode) {
        SkyPass s = null;
        TerrainPass t = null;
        ObjectsPass o = null;
        try {
            s = new SkyPass();
            t = new TerrainPass(course, surface, mode);
            o = new ObjectsPass(course, surface);
            water = new WaterPass(course, surface);
        } catch (RuntimeException e) {
            for (RenderPass p : new RenderPass[]{o, t, s}) if (p != null) p.close();
            throw e;
        }
        sky = s;
        terrain = t;
        objects = o;
        passes = List.of(sky, terrain, objects, water);
    }

    public TerrainPass terrainPass() {
        return terrain;
    }

    public ObjectsPass objectsPass() {
        return objects;
    }

    public WaterPass waterPass() {
        return water;
    }

    public Vector3f ballCenter() {
        return objects.ballCenter();
    }

    /** Renders one frame into the currently bound framebuffer, whose size is width x height pixels. */
    public void render(OrbitCamera camera, int width, int height, float time) {
        glViewport(0, 0, width, height);
        glClearColor(0.62f, 0.78f, 0.93f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDisable(GL_CULL_FACE);
        glEnable(GL_MULTISAMPLE);
        frame.update(camera, width, height, time);
        for (RenderPass pass : passes) pass.render(frame);
    }

    @Override
    public void close() {
        for (int i = passes.size() - 1; i >= 0; i--) passes.get(i).close();
    }
}
