package minigolf.render;

import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.system.MemoryStack;

import java.nio.IntBuffer;

import static org.lwjgl.glfw.Callbacks.glfwFreeCallbacks;
import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.system.MemoryUtil.NULL;

/**
 * A GLFW window with an OpenGL 3.3 core (forward-compatible) context, current on the thread that
 * created it. GLFW is initialised by the first open window and terminated when the last one closes.
 * The viewport size to use is {@link #framebufferWidth()} x {@link #framebufferHeight()}: pixels, not
 * screen coordinates, so HiDPI screens render at full resolution; it follows resizes.
 * <p>
 * A hidden window (off-screen rendering: stills, benchmarks, tests) on a Linux machine with no display
 * is no window at all but a {@link SurfacelessContext} (EGL without a display server); it has no default
 * framebuffer, which off-screen code never uses. {@code -Dminigolf.gl=surfaceless} (or the environment
 * variable {@code MINIGOLF_GL}) forces that path, {@code glfw} forbids it. With neither a display nor
 * EGL, the constructor throws {@link NoOpenGlException}.
 */
public final class Window implements AutoCloseable {

    /** How to open the window. {@code samples} 0 means no multisampling for the default framebuffer. */
    public record Options(boolean visible, boolean vsync, int samples, boolean resizable,
                          int glMajor, int glMinor) {
        public static Options visibleDefaults() {
            return new Options(true, true, 4, true, 3, 3);
        }

        /** A hidden window for off-screen rendering (screenshots, tests). */
        public static Options hidden() {
            return new Options(false, false, 0, false, 3, 3);
        }

        public Options withGlVersion(int major, int minor) {
            return new Options(visible, vsync, samples, resizable, major, minor);
        }
    }

    private static int openWindows;
    private static GLFWErrorCallback errorCallback;
    private static volatile String lastError = "";

    private final long handle;
    private final SurfacelessContext surfaceless;
    private boolean closeRequested;
    private int fbWidth;
    private int fbHeight;
    private boolean closed;
    private int windowedX = 80, windowedY = 80, windowedW = 1280, windowedH = 800;

    public Window(String title, int width, int height, Options options) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("window size must be positive: " + width + "x" + height);
        }
        String backend = backendOverride();
        boolean mayUseEgl = !options.visible() && !"glfw".equals(backend);
        if (mayUseEgl && ("surfaceless".equals(backend) || !hasDisplay())) {
            handle = NULL;
            surfaceless = createSurfaceless(options, null);
            fbWidth = width;
            fbHeight = height;
            return;
        }
        try {
            if (!hasDisplay()) {
                // Not even tried: GLFW's probe of Wayland would print a libwayland warning first.
                throw new NoOpenGlException("no display for a window (DISPLAY is unset; render and bench-render"
                        + " work without one)");
            }
            acquireGlfw();
        } catch (NoOpenGlException e) {
            if (!mayUseEgl) throw e;
            // A display that cannot be opened (a stale DISPLAY, say): render without it.
            handle = NULL;
            surfaceless = createSurfaceless(options, e.getMessage());
            fbWidth = width;
            fbHeight = height;
            return;
        }
        surfaceless = null;
        boolean ok = false;
        try {
            glfwDefaultWindowHints();
            glfwWindowHint(GLFW_VISIBLE, options.visible() ? GLFW_TRUE : GLFW_FALSE);
            glfwWindowHint(GLFW_RESIZABLE, options.resizable() ? GLFW_TRUE : GLFW_FALSE);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, options.glMajor());
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, options.glMinor());
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
            glfwWindowHint(GLFW_SAMPLES, Math.max(0, options.samples()));
            glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
            lastError = "";
            handle = glfwCreateWindow(width, height, title, NULL, NULL);
            if (handle == NULL) {
                throw new RenderException("Could not create a window with an OpenGL " + options.glMajor() + "."
                        + options.glMinor() + " core context: " + describeLastError());
            }
            glfwMakeContextCurrent(handle);
            try {
                GL.createCapabilities();
            } catch (RuntimeException e) {
                glfwDestroyWindow(handle);
                throw new RenderException("OpenGL functions could not be loaded for the new context: " + e.getMessage(), e);
            }
            glfwSwapInterval(options.vsync() ? 1 : 0);
            if (options.visible()) fitToScreen();
            try (MemoryStack stack = MemoryStack.stackPush()) {
                IntBuffer w = stack.mallocInt(1);
                IntBuffer h = stack.mallocInt(1);
                glfwGetFramebufferSize(handle, w, h);
                fbWidth = w.get(0);
                fbHeight = h.get(0);
            }
            glfwSetFramebufferSizeCallback(handle, (win, w, h) -> {
                fbWidth = w;
                fbHeight = h;
            });
            ok = true;
        } finally {
            if (!ok) releaseGlfw();
        }
    }

    /** A window asked for larger than the screen's work area (a 1366 x 768 laptop) is made to fit it. */
    private void fitToScreen() {
        long monitor = glfwGetPrimaryMonitor();
        if (monitor == NULL) return;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer ax = stack.mallocInt(1), ay = stack.mallocInt(1), aw = stack.mallocInt(1), ah = stack.mallocInt(1);
            IntBuffer w = stack.mallocInt(1), h = stack.mallocInt(1);
            glfwGetMonitorWorkarea(monitor, ax, ay, aw, ah);
            glfwGetWindowSize(handle, w, h);
            int[] fitted = fitted(w.get(0), h.get(0), aw.get(0), ah.get(0));
            if (fitted[0] != w.get(0) || fitted[1] != h.get(0)) {
                glfwSetWindowSize(handle, fitted[0], fitted[1]);
                glfwSetWindowPos(handle, ax.get(0), ay.get(0));
            }
        }
    }

    /**
     * The window size (w, h) fitted inside a work area (areaW x areaH), keeping 40 pixels for the
     * title bar; unchanged when it fits or the area is unknown (0).
     */
    static int[] fitted(int w, int h, int areaW, int areaH) {
        if (areaW <= 0 || areaH <= 0) return new int[]{w, h};
        return new int[]{Math.max(320, Math.min(w, areaW)), Math.max(200, Math.min(h, areaH - 40))};
    }

    private static SurfacelessContext createSurfaceless(Options options, String glfwProblem) {
        try {
            return SurfacelessContext.create(options.glMajor(), options.glMinor());
        } catch (RenderException e) {
            if (e.getMessage().contains("could not create an OpenGL")) throw e; // EGL works; the version does not
            String why = glfwProblem != null ? glfwProblem + "; and without a display: " + e.getMessage()
                    : (hasDisplay() ? "" : "no display (DISPLAY is unset) and ") + "no display-less OpenGL: " + e.getMessage();
            throw new NoOpenGlException("no OpenGL available: " + why);
        }
    }

    /** -Dminigolf.gl or MINIGOLF_GL: "surfaceless" (EGL, even with a display) or "glfw" (never EGL). */
    private static String backendOverride() {
        String v = System.getProperty("minigolf.gl");
        if (v == null) v = System.getenv("MINIGOLF_GL");
        return v == null ? "" : v.trim().toLowerCase(java.util.Locale.ROOT);
    }

    /** On Linux a window needs an X server or a Wayland compositor; Windows and macOS always have a desktop. */
    private static boolean hasDisplay() {
        if (org.lwjgl.system.Platform.get() != org.lwjgl.system.Platform.LINUX) return true;
        return !isBlank(System.getenv("DISPLAY")) || !isBlank(System.getenv("WAYLAND_DISPLAY"));
    }

    private static boolean isBlank(String s) {
        return s == null || s.isBlank();
    }

    private static synchronized void acquireGlfw() {
        if (openWindows == 0) {
            // The error callback goes first so that a failing glfwInit can say why.
            errorCallback = GLFWErrorCallback.create((code, description) ->
                    lastError = String.format("GLFW error 0x%X: %s", code, GLFWErrorCallback.getDescription(description)));
            GLFWErrorCallback previous = glfwSetErrorCallback(errorCallback);
            if (previous != null) previous.free();
            // With only an X display, ask for X11 straight away: probing Wayland first makes libwayland print
            // "XDG_RUNTIME_DIR is invalid or not set" when that variable is unset (ssh, xvfb-run, CI).
            boolean x11Only = org.lwjgl.system.Platform.get() == org.lwjgl.system.Platform.LINUX
                    && !isBlank(System.getenv("DISPLAY")) && isBlank(System.getenv("WAYLAND_DISPLAY"))
                    && glfwPlatformSupported(GLFW_PLATFORM_X11);
            if (x11Only) glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
            boolean ok = glfwInit();
            // Seen here (Xvfb, Mesa): once a GL context has existed and GLFW was terminated, the next
            // X11 connection of the process fails once ("Failed to open display") and the one after works.
            if (!ok && x11Only) ok = glfwInit();
            if (x11Only) glfwInitHint(GLFW_PLATFORM, GLFW_ANY_PLATFORM);
            if (!ok && !x11Only && System.getenv("DISPLAY") != null && glfwPlatformSupported(GLFW_PLATFORM_X11)) {
                // A stale WAYLAND_DISPLAY (no compositor) makes auto-detection fail though X11 would work.
                String first = describeLastError();
                glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
                ok = glfwInit();
                glfwInitHint(GLFW_PLATFORM, GLFW_ANY_PLATFORM);
                if (!ok) lastError = first + "; with X11 forced: " + describeLastError();
            }
            if (!ok) {
                String why = describeLastError();
                glfwSetErrorCallback(null);
                errorCallback.free();
                errorCallback = null;
                throw new NoOpenGlException("GLFW could not be initialised (is there a display? DISPLAY="
                        + System.getenv("DISPLAY") + "): " + why + staleXauthorityHint());
            }
        }
        openWindows++;
    }

    private static synchronized void releaseGlfw() {
        if (--openWindows == 0) {
            glfwTerminate();
            GLFWErrorCallback cb = glfwSetErrorCallback(null);
            if (cb != null) cb.free();
            errorCallback = null;
        }
    }

    /** A Gradle daemon started under an earlier xvfb-run keeps that run's (deleted) XAUTHORITY file. */
    private static String staleXauthorityHint() {
        String xauth = System.getenv("XAUTHORITY");
        if (xauth != null && !new java.io.File(xauth).exists()) {
            return ". XAUTHORITY=" + xauth + " does not exist: this process inherited the environment of an"
                    + " earlier X session (a long-lived Gradle daemon? try --no-daemon)";
        }
        return "";
    }

    private static String describeLastError() {
        return lastError.isEmpty() ? "no GLFW error reported" : lastError;
    }

    /** The GLFW window, or NULL (0) for a display-less context. */
    public long handle() {
        return handle;
    }

    public int framebufferWidth() {
        return fbWidth;
    }

    public int framebufferHeight() {
        return fbHeight;
    }

    /** True for a display-less EGL context: there is no window, no default framebuffer and no input. */
    public boolean isSurfaceless() {
        return surfaceless != null;
    }

    /** The EGL platform of a display-less context, or null for a GLFW window. */
    SurfacelessContext.Kind eglPlatform() {
        return surfaceless == null ? null : surfaceless.kind();
    }

    public boolean shouldClose() {
        return surfaceless != null ? closeRequested : glfwWindowShouldClose(handle);
    }

    public void requestClose() {
        if (surfaceless != null) closeRequested = true;
        else glfwSetWindowShouldClose(handle, true);
    }

    public void swapBuffers() {
        if (surfaceless == null) glfwSwapBuffers(handle);
    }

    public void pollEvents() {
        if (surfaceless == null) glfwPollEvents();
    }

    /** Vsync on or off (the game's frame limiter takes over when it is off or has no effect). */
    public void setVsync(boolean on) {
        if (surfaceless == null) glfwSwapInterval(on ? 1 : 0);
    }

    public boolean isFullscreen() {
        return surfaceless == null && glfwGetWindowMonitor(handle) != NULL;
    }

    /** Switches between a window and the primary monitor's full screen (F11), restoring the window's place. */
    public void toggleFullscreen() {
        if (surfaceless != null) return;
        if (isFullscreen()) {
            glfwSetWindowMonitor(handle, NULL, windowedX, windowedY, windowedW, windowedH, GLFW_DONT_CARE);
            return;
        }
        long monitor = glfwGetPrimaryMonitor();
        if (monitor == NULL) return;
        org.lwjgl.glfw.GLFWVidMode mode = glfwGetVideoMode(monitor);
        if (mode == null) return;
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer x = stack.mallocInt(1), y = stack.mallocInt(1), w = stack.mallocInt(1), h = stack.mallocInt(1);
            glfwGetWindowPos(handle, x, y);
            glfwGetWindowSize(handle, w, h);
            windowedX = x.get(0);
            windowedY = y.get(0);
            windowedW = Math.max(320, w.get(0));
            windowedH = Math.max(200, h.get(0));
        }
        glfwSetWindowMonitor(handle, monitor, 0, 0, mode.width(), mode.height(), mode.refreshRate());
    }

    /** Minimised (iconified): nothing to draw. */
    public boolean isIconified() {
        return surfaceless == null && glfwGetWindowAttrib(handle, GLFW_ICONIFIED) == GLFW_TRUE;
    }

    /** The most characters of a title (a course's name is part of it; GLFW encodes it on a small native stack). */
    static final int MAX_TITLE_CHARS = 200;

    public void setTitle(String title) {
        if (surfaceless == null) glfwSetWindowTitle(handle, shortTitle(title));
    }

    /** The title cut to {@link #MAX_TITLE_CHARS} with "..." (never splitting a surrogate pair). */
    public static String shortTitle(String title) {
        if (title.length() <= MAX_TITLE_CHARS) return title;
        int n = MAX_TITLE_CHARS - 3;
        if (Character.isHighSurrogate(title.charAt(n - 1))) n--;
        return title.substring(0, n) + "...";
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        if (surfaceless != null) {
            surfaceless.close();
            return;
        }
        if (glfwGetCurrentContext() == handle) {
            GL.setCapabilities(null);
            glfwMakeContextCurrent(NULL);
        }
        glfwFreeCallbacks(handle);
        glfwDestroyWindow(handle);
        releaseGlfw();
    }
}
