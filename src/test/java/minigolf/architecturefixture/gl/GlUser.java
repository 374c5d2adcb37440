package minigolf.architecturefixture.gl;

import org.lwjgl.opengl.GL11;

/** A class that calls OpenGL: ArchitectureTest shows its no-OpenGL rule reports it. Never run. */
public final class GlUser {
    public void flush() {
        GL11.glFlush();
    }
}
