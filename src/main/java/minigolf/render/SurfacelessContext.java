package minigolf.render;

import org.lwjgl.egl.EGL;
import org.lwjgl.egl.EGLCapabilities;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.JNI;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.Platform;

import java.nio.IntBuffer;

import org.lwjgl.PointerBuffer;

import static org.lwjgl.egl.EGL10.*;
import static org.lwjgl.egl.EGL12.eglBindAPI;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_API;
import static org.lwjgl.egl.EGL15.*;

/**
 * An OpenGL core context with no window and no display server: EGL on Mesa's "surfaceless" platform
 * (EGL_MESA_platform_surfaceless, in Debian's libegl-mesa0), made current without any surface. Off-screen
 * rendering draws into its own framebuffer objects, so this is all it needs; it runs over SSH, in
 * containers and in CI without Xvfb. Linux only (elsewhere a hidden GLFW window is used).
 */
final class SurfacelessContext implements AutoCloseable {
    private static final int EGL_PLATFORM_SURFACELESS_MESA = 0x31DD;

    private final long display;
    private final long context;
    private boolean closed;

    private SurfacelessContext(long display, long context) {
        this.display = display;
        this.context = context;
    }

    /** Why EGL cannot work in this process (found once; LWJGL does not retry loading libEGL). */
    private static volatile String unavailable;

    /** Creates the context and makes it current on this thread, or throws a RenderException saying why not. */
    static SurfacelessContext create(int glMajor, int glMinor) {
        if (unavailable != null) throw new RenderException(unavailable);
        if (Platform.get() != Platform.LINUX) {
            throw new RenderException("no display-less OpenGL on " + Platform.get().getName());
        }
        try {
            EGL.getCapabilities();
        } catch (Throwable e) { // libEGL.so.1 missing: the class initialiser fails with an Error
            unavailable = "no libEGL (install libegl1 and libegl-mesa0): " + e.getMessage();
            throw new RenderException(unavailable, e);
        }
        String clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (clientExtensions == null || !clientExtensions.contains("EGL_MESA_platform_surfaceless")) {
            throw new RenderException("EGL has no surfaceless platform (Mesa's libegl-mesa0 provides it)");
        }
        // LWJGL's capabilities leave eglGetPlatformDisplay unloaded with libglvnd, so ask EGL for it directly.
        long getPlatformDisplay = eglGetProcAddress("eglGetPlatformDisplayEXT");
        if (getPlatformDisplay == 0) getPlatformDisplay = eglGetProcAddress("eglGetPlatformDisplay");
        if (getPlatformDisplay == 0) throw new RenderException("EGL has no eglGetPlatformDisplay");
        long display = JNI.callPPP(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, 0L, getPlatformDisplay);
        if (display == EGL_NO_DISPLAY) throw new RenderException("EGL: no surfaceless display: " + error());
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer major = stack.mallocInt(1), minor = stack.mallocInt(1);
            if (!eglInitialize(display, major, minor)) {
                throw new RenderException("EGL: the surfaceless display did not initialise: " + error());
            }
            boolean ok = false;
            try {
                EGLCapabilities caps = EGL.createDisplayCapabilities(display, major.get(0), minor.get(0));
                if (!caps.EGL_KHR_surfaceless_context) {
                    throw new RenderException("EGL: no EGL_KHR_surfaceless_context");
                }
                if (!eglBindAPI(EGL_OPENGL_API)) throw new RenderException("EGL: no desktop OpenGL: " + error());
                // Any OpenGL configuration will do: everything is drawn into framebuffer objects. (The
                // default surface type, window, does not exist on this platform.)
                IntBuffer configAttribs = stack.ints(
                        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE);
                PointerBuffer configs = stack.mallocPointer(1);
                IntBuffer count = stack.mallocInt(1);
                if (!eglChooseConfig(display, configAttribs, configs, count) || count.get(0) == 0) {
                    throw new RenderException("EGL: no OpenGL framebuffer configuration: " + error());
                }
                IntBuffer contextAttribs = stack.ints(
                        EGL_CONTEXT_MAJOR_VERSION, glMajor, EGL_CONTEXT_MINOR_VERSION, glMinor,
                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                        EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE, EGL_TRUE, EGL_NONE);
                long context = eglCreateContext(display, configs.get(0), EGL_NO_CONTEXT, contextAttribs);
                if (context == EGL_NO_CONTEXT) {
                    throw new RenderException("EGL: could not create an OpenGL " + glMajor + "." + glMinor
                            + " core context: " + error());
                }
                if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
                    String why = error();
                    eglDestroyContext(display, context);
                    throw new RenderException("EGL: could not make the context current: " + why);
                }
                try {
                    GL.createCapabilities();
                } catch (RuntimeException e) {
                    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                    eglDestroyContext(display, context);
                    throw new RenderException("OpenGL functions could not be loaded for the EGL context: "
                            + e.getMessage(), e);
                }
                ok = true;
                return new SurfacelessContext(display, context);
            } finally {
                if (!ok) eglTerminate(display);
            }
        }
    }

    private static String error() {
        return String.format("EGL error 0x%X", eglGetError());
    }

    boolean isCurrent() {
        return eglGetCurrentContext() == context;
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        if (isCurrent()) {
            GL.setCapabilities(null);
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(display, context);
        eglTerminate(display);
    }

}
