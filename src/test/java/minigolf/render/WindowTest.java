package minigolf.render;

import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryStack;

import java.nio.ByteBuffer;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.*;

/** Hidden windows: a GLFW window under a display, an EGL surfaceless context without one (both tested). */
class WindowTest {
    @Test
    void hiddenWindowHasACoreContextAndAFramebuffer() {
        try (Window w = new Window("test", 320, 200, Window.Options.hidden())) {
            assertTrue(w.framebufferWidth() > 0 && w.framebufferHeight() > 0);
            assertEquals(!Displays.present(), w.isSurfaceless(), "EGL exactly when there is no display");
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
        assertTrue(e.getMessage().contains("GLFW error") || e.getMessage().contains("EGL error"), e.getMessage());
        assertFalse(e instanceof NoOpenGlException, "OpenGL exists, only not 9.9: " + e.getMessage());
        // The library is left in a usable state: a normal window opens afterwards.
        try (Window w = new Window("test", 64, 64, Window.Options.hidden())) {
            assertTrue(w.framebufferWidth() > 0);
        }
    }

    /** GLFW is terminated when the last window closes and initialised again for the next (the game's probe, then its window). */
    @Test
    void windowsOpenOneAfterAnother() {
        for (int i = 0; i < 3; i++) {
            try (Window w = new Window("test " + i, 64, 64, Window.Options.hidden())) {
                assertTrue(glGetInteger(org.lwjgl.opengl.GL30.GL_MAJOR_VERSION) >= 3, "round " + i);
            }
        }
    }

    /** The display-less path, forced, so that it is also tested where a display exists (CI under Xvfb). */
    @Test
    void surfacelessContextDrawsIntoAFramebuffer() {
        String before = System.getProperty("minigolf.gl");
        System.setProperty("minigolf.gl", "surfaceless");
        try (Window w = new Window("test", 64, 64, Window.Options.hidden());
             Framebuffer target = new Framebuffer(8, 4, 0);
             MemoryStack stack = MemoryStack.stackPush()) {
            assertTrue(w.isSurfaceless());
            assertEquals(0L, w.handle());
            assertTrue(glGetInteger(org.lwjgl.opengl.GL30.GL_MAJOR_VERSION) * 10
                    + glGetInteger(org.lwjgl.opengl.GL30.GL_MINOR_VERSION) >= 33, glGetString(GL_VERSION));
            assertTrue((glGetInteger(org.lwjgl.opengl.GL32.GL_CONTEXT_PROFILE_MASK)
                    & org.lwjgl.opengl.GL32.GL_CONTEXT_CORE_PROFILE_BIT) != 0, "not a core profile");
            target.bind();
            glClearColor(1f, 0.5f, 0.25f, 1f);
            glClear(GL_COLOR_BUFFER_BIT);
            ByteBuffer pixels = stack.malloc(8 * 4 * 4);
            target.readPixels(pixels);
            for (int i = 0; i < 8 * 4; i++) {
                assertEquals(255, pixels.get(4 * i) & 0xFF);
                assertEquals(128, pixels.get(4 * i + 1) & 0xFF, 1.0);
                assertEquals(64, pixels.get(4 * i + 2) & 0xFF, 1.0);
            }
            w.swapBuffers(); // no window: nothing to swap, and no crash
            w.pollEvents();
        } finally {
            if (before == null) System.clearProperty("minigolf.gl");
            else System.setProperty("minigolf.gl", before);
        }
    }
}
