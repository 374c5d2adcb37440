package minigolf.render;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.*;

/** Needs a display (run under xvfb-run); fails, with GLFW's reason, when there is none. */
class WindowTest {
    @Test
    void hiddenWindowHasACoreContextAndAFramebuffer() {
        try (Window w = new Window("test", 320, 200, Window.Options.hidden())) {
            assertTrue(w.framebufferWidth() > 0 && w.framebufferHeight() > 0);
            String version = glGetString(GL_VERSION);
            assertNotNull(version);
            assertTrue(glGetInteger(org.lwjgl.opengl.GL30.GL_MAJOR_VERSION) >= 3, version);
            assertFalse(w.shouldClose());
            w.requestClose();
            assertTrue(w.shouldClose());
        }
    }

    @Test
    void impossibleContextIsAnExceptionWithAMessage() {
        RenderException e = assertThrows(RenderException.class,
                () -> new Window("test", 64, 64, Window.Options.hidden().withGlVersion(9, 9)));
        assertTrue(e.getMessage().contains("9.9"), e.getMessage());
        assertTrue(e.getMessage().contains("GLFW error"), e.getMessage());
        // GLFW is left in a usable state: a normal window opens afterwards.
        try (Window w = new Window("test", 64, 64, Window.Options.hidden())) {
            assertTrue(w.framebufferWidth() > 0);
        }
    }
}
