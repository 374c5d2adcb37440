package minigolf.render;

import org.lwjgl.egl.EGL;
import org.lwjgl.egl.EGLCapabilities;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.JNI;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.lwjgl.system.Platform;

import java.nio.IntBuffer;
import java.util.Locale;

import org.lwjgl.PointerBuffer;

import static org.lwjgl.egl.EGL10.*;
import static org.lwjgl.egl.EGL12.eglBindAPI;
import static org.lwjgl.egl.EGL12.eglReleaseThread;
import static org.lwjgl.egl.EGL14.EGL_OPENGL_API;
import static org.lwjgl.egl.EGL15.*;

/**
 * An OpenGL core context with no window and no display server, made current without any surface
 * (EGL_KHR_surfaceless_context): off-screen rendering draws into its own framebuffer objects, so
 * this is all it needs; it runs over SSH, in containers and in CI without Xvfb. Linux only
 * (elsewhere a hidden GLFW window is used).
 *
 * <p>Two EGL platforms give such a display: Mesa's "surfaceless" one (EGL_MESA_platform_surfaceless,
 * in Debian's libegl-mesa0), used where it exists, and the device platform (EGL_EXT_platform_device
 * with EGL_EXT_device_enumeration), which NVIDIA's driver offers; there a hardware device is taken
 * before a software one. {@code -Dminigolf.egl} or {@code MINIGOLF_EGL} = {@code surfaceless} or
 * {@code device} forces one.
 *
 * <p>{@link #close()} tears EGL down in the order NVIDIA's driver needs: release the context from
 * the thread, destroy the context, terminate the display, release the thread's EGL state. Without
 * the last two its library crashed the JVM at exit (SIGSEGV in a native thread of libEGL_nvidia,
 * exit code 134) after every headless render.
 */
final class SurfacelessContext implements AutoCloseable {
    private static final int EGL_PLATFORM_SURFACELESS_MESA = 0x31DD;
    private static final int EGL_PLATFORM_DEVICE_EXT = 0x313F;
    /** How many EGL devices are looked at, at most. */
    private static final int MAX_DEVICES = 16;

    /** The two platforms, as named in the override and in messages. */
    enum Kind {
        SURFACELESS("surfaceless"), DEVICE("device");

        final String label;

        Kind(String label) {
            this.label = label;
        }
    }

    private final long display;
    private final long context;
    private final Kind kind;
    private boolean closed;

    private SurfacelessContext(long display, long context, Kind kind) {
        this.display = display;
        this.context = context;
        this.kind = kind;
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
        Kind kind = choosePlatform(clientExtensions, override());
        // LWJGL's capabilities leave eglGetPlatformDisplay unloaded with libglvnd, so ask EGL for it directly.
        long getPlatformDisplay = eglGetProcAddress("eglGetPlatformDisplayEXT");
        if (getPlatformDisplay == 0) getPlatformDisplay = eglGetProcAddress("eglGetPlatformDisplay");
        if (getPlatformDisplay == 0) throw new RenderException("EGL has no eglGetPlatformDisplay");
        long display = kind == Kind.SURFACELESS
                ? JNI.callPPP(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, 0L, getPlatformDisplay)
                : JNI.callPPP(EGL_PLATFORM_DEVICE_EXT, chooseDevice(), 0L, getPlatformDisplay);
        if (display == EGL_NO_DISPLAY) throw new RenderException("EGL: no " + kind.label + " display: " + error());
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer major = stack.mallocInt(1), minor = stack.mallocInt(1);
            if (!eglInitialize(display, major, minor)) {
                throw new RenderException("EGL: the " + kind.label + " display did not initialise: " + error());
            }
            boolean ok = false;
            try {
                EGLCapabilities caps = EGL.createDisplayCapabilities(display, major.get(0), minor.get(0));
                if (!caps.EGL_KHR_surfaceless_context) {
                    throw new RenderException("EGL: no EGL_KHR_surfaceless_context");
                }
                if (!eglBindAPI(EGL_OPENGL_API)) throw new RenderException("EGL: no desktop OpenGL: " + error());
                // Any OpenGL configuration will do: everything is drawn into framebuffer objects. (The
                // default surface type, window, does not exist on these platforms.)
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
                return new SurfacelessContext(display, context, kind);
            } finally {
                if (!ok) {
                    eglTerminate(display);
                    eglReleaseThread();
                }
            }
        }
    }

    /**
     * The platform to use from EGL's client extensions: the forced one ({@code surfaceless} or
     * {@code device}, else null), else Mesa's surfaceless platform where it exists, else the device
     * platform; a RenderException when the one needed is missing.
     */
    static Kind choosePlatform(String clientExtensions, String forced) {
        String ext = clientExtensions == null ? "" : clientExtensions;
        boolean surfaceless = ext.contains("EGL_MESA_platform_surfaceless");
        boolean device = ext.contains("EGL_EXT_platform_device") && ext.contains("EGL_EXT_device_enumeration");
        if (forced != null && !forced.isEmpty()) {
            if (forced.equals(Kind.SURFACELESS.label)) {
                if (!surfaceless) throw new RenderException("EGL has no surfaceless platform (asked for by minigolf.egl)");
                return Kind.SURFACELESS;
            }
            if (forced.equals(Kind.DEVICE.label)) {
                if (!device) throw new RenderException("EGL has no device platform (EGL_EXT_platform_device, asked for by minigolf.egl)");
                return Kind.DEVICE;
            }
            throw new RenderException("minigolf.egl must be surfaceless or device, got '" + forced + "'");
        }
        if (surfaceless) return Kind.SURFACELESS;
        if (device) return Kind.DEVICE;
        throw new RenderException("EGL has neither Mesa's surfaceless platform (libegl-mesa0) nor the device"
                + " platform (EGL_EXT_platform_device, NVIDIA's driver)");
    }

    /** -Dminigolf.egl or MINIGOLF_EGL, lower case, or null. */
    private static String override() {
        String v = System.getProperty("minigolf.egl");
        if (v == null) v = System.getenv("MINIGOLF_EGL");
        return v == null ? null : v.trim().toLowerCase(Locale.ROOT);
    }

    /** The first hardware EGL device (not Mesa's software one), else the first device. */
    private static long chooseDevice() {
        long queryDevices = eglGetProcAddress("eglQueryDevicesEXT");
        long queryDeviceString = eglGetProcAddress("eglQueryDeviceStringEXT");
        if (queryDevices == 0) throw new RenderException("EGL has no eglQueryDevicesEXT");
        try (MemoryStack stack = MemoryStack.stackPush()) {
            PointerBuffer devices = stack.mallocPointer(MAX_DEVICES);
            IntBuffer count = stack.mallocInt(1);
            if (JNI.callPPI(MAX_DEVICES, MemoryUtil.memAddress(devices), MemoryUtil.memAddress(count), queryDevices) == 0
                    || count.get(0) < 1) {
                throw new RenderException("EGL: no devices: " + error());
            }
            int n = Math.min(MAX_DEVICES, count.get(0));
            for (int i = 0; i < n; i++) {
                String ext = queryDeviceString == 0 ? null
                        : MemoryUtil.memASCIISafe(JNI.callPP(devices.get(i), EGL_EXTENSIONS, queryDeviceString));
                if (!isSoftwareDevice(ext)) return devices.get(i);
            }
            return devices.get(0);
        }
    }

    /** Whether a device's extension string marks Mesa's software rasteriser. */
    static boolean isSoftwareDevice(String deviceExtensions) {
        return deviceExtensions != null && deviceExtensions.contains("EGL_MESA_device_software");
    }

    private static String error() {
        return String.format("EGL error 0x%X", eglGetError());
    }

    /** Which platform the display is on. */
    Kind kind() {
        return kind;
    }

    boolean isCurrent() {
        return eglGetCurrentContext() == context;
    }

    /**
     * Release current, destroy the context, terminate the display, release the thread: the order
     * NVIDIA's libEGL needs to exit cleanly (and harmless on Mesa).
     */
    @Override
    public void close() {
        if (closed) return;
        closed = true;
        if (isCurrent()) GL.setCapabilities(null);
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        eglReleaseThread();
    }
}
