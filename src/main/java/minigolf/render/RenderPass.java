package minigolf.render;

/** One stage of a frame (sky, terrain, water, objects; later shadows, reflections, HUD). Owns its GL resources. */
public interface RenderPass extends AutoCloseable {
    void render(FrameContext frame);

    @Override
    void close();
}
