package minigolf.render;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

/** The procedural sky dome (gradient, sun, drifting clouds; see sky.frag): one full-screen triangle, no depth writes. Drawn first. */
public final class SkyPass implements RenderPass {
    private final ShaderProgram shader = ShaderProgram.load("sky");
    private final int emptyVao = glGenVertexArrays();

    @Override
    public void render(FrameContext frame) {
        glDepthMask(false);
        glDisable(GL_DEPTH_TEST);
        shader.use();
        shader.set("uInverseViewProjection", frame.inverseViewProjection);
        shader.set("uSunDirection", frame.sun.direction());
        shader.set("uTime", frame.time);
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
    }

    @Override
    public void close() {
        shader.close();
        glDeleteVertexArrays(emptyVao);
    }
}
