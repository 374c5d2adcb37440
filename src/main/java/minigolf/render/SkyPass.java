package minigolf.render;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL30.*;

/** The procedural sky dome (gradient, sun, drifting clouds; see sky.frag): one full-screen triangle at the far plane, no depth writes. Drawn after the opaque passes. */
public final class SkyPass implements RenderPass {
    private final ShaderProgram shader = ShaderProgram.load("sky");
    private final int emptyVao = glGenVertexArrays();

    @Override
    public void render(FrameContext frame) {
        // Drawn after the opaque passes: at depth 1 (the far plane) with GL_LEQUAL it fills only the
        // pixels nothing covered, so the cloud noise is not computed under the course (early depth test).
        glDepthMask(false);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        shader.use();
        shader.set("uInverseViewProjection", frame.inverseViewProjection);
        shader.set("uSunDirection", frame.sun.direction());
        shader.set("uTime", frame.time);
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glDepthMask(true);
    }

    @Override
    public void close() {
        shader.close();
        glDeleteVertexArrays(emptyVao);
    }
}
