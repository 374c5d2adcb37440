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
        withProperties("surfaceless", null, () -> drawsIntoAFramebuffer(SurfacelessContext.Kind.SURFACELESS));
    }

    /**
     * The EGL device platform (NVIDIA's way to a display-less context), forced: Mesa offers it too,
     * with its software device, so the same code path runs here. Three rounds: each context is torn
     * down (release, destroy, terminate, release thread) and a fresh one starts cleanly after it.
     */
    @Test
    void deviceContextDrawsIntoAFramebufferAndTearsDown() {
        String ext = clientExtensions();
        org.junit.jupiter.api.Assumptions.assumeTrue(ext != null && ext.contains("EGL_EXT_platform_device")
                && ext.contains("EGL_EXT_device_enumeration"), "this EGL has no device platform: " + ext);
        for (int round = 0; round < 3; round++) {
            withProperties("surfaceless", "device", () -> drawsIntoAFramebuffer(SurfacelessContext.Kind.DEVICE));
            assertEquals(0L, org.lwjgl.egl.EGL14.eglGetCurrentContext(), "round " + round + ": a context is still current");
        }
    }

    private static String clientExtensions() {
        try {
            org.lwjgl.egl.EGL.getCapabilities();
            return org.lwjgl.egl.EGL10.eglQueryString(org.lwjgl.egl.EGL10.EGL_NO_DISPLAY, org.lwjgl.egl.EGL10.EGL_EXTENSIONS);
        } catch (Throwable e) {
            return null;
        }
    }

    @Test
    void thePlatformIsMesasSurfacelessWhereItExistsElseTheDevicePlatform() {
        String mesa = "EGL_EXT_client_extensions EGL_EXT_device_enumeration EGL_EXT_platform_device EGL_MESA_platform_surfaceless";
        String nvidia = "EGL_EXT_client_extensions EGL_EXT_device_base EGL_EXT_device_enumeration EGL_EXT_platform_device EGL_KHR_platform_x11";
        assertEquals(SurfacelessContext.Kind.SURFACELESS, SurfacelessContext.choosePlatform(mesa, null));
        assertEquals(SurfacelessContext.Kind.DEVICE, SurfacelessContext.choosePlatform(nvidia, null));
        assertEquals(SurfacelessContext.Kind.DEVICE, SurfacelessContext.choosePlatform(mesa, "device"));
        RenderException none = assertThrows(RenderException.class,
                () -> SurfacelessContext.choosePlatform("EGL_EXT_client_extensions EGL_KHR_platform_x11", null));
        assertTrue(none.getMessage().contains("neither Mesa's surfaceless platform"), none.getMessage());
        RenderException forced = assertThrows(RenderException.class, () -> SurfacelessContext.choosePlatform(nvidia, "surfaceless"));
        assertTrue(forced.getMessage().contains("no surfaceless platform"), forced.getMessage());
        RenderException bad = assertThrows(RenderException.class, () -> SurfacelessContext.choosePlatform(mesa, "gbm"));
        assertEquals("minigolf.egl must be surfaceless or device, got 'gbm'", bad.getMessage());
        assertTrue(SurfacelessContext.isSoftwareDevice("EGL_MESA_device_software EGL_EXT_device_drm"));
        assertFalse(SurfacelessContext.isSoftwareDevice("EGL_NV_device_cuda EGL_EXT_device_drm"));
        assertFalse(SurfacelessContext.isSoftwareDevice(null));
    }

    private static void withProperties(String gl, String egl, Runnable body) {
        String beforeGl = System.getProperty("minigolf.gl"), beforeEgl = System.getProperty("minigolf.egl");
        System.setProperty("minigolf.gl", gl);
        if (egl != null) System.setProperty("minigolf.egl", egl);
        try {
            body.run();
        } finally {
            if (beforeGl == null) System.clearProperty("minigolf.gl");
            else System.setProperty("minigolf.gl", beforeGl);
            if (beforeEgl == null) System.clearProperty("minigolf.egl");
            else System.setProperty("minigolf.egl", beforeEgl);
        }
    }

    private static void drawsIntoAFramebuffer(SurfacelessContext.Kind kind) {
        try (Window w = new Window("test", 64, 64, Window.Options.hidden());
             Framebuffer target = new Framebuffer(8, 4, 0);
             MemoryStack stack = MemoryStack.stackPush()) {
            assertTrue(w.isSurfaceless());
            assertEquals(kind, w.eglPlatform());
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
        }
    }
}
