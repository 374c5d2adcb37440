package minigolf.ui;

import java.nio.ByteBuffer;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import minigolf.render.ShaderProgram;
import org.lwjgl.glfw.GLFWCharCallback;
import org.lwjgl.glfw.GLFWCharCallbackI;
import org.lwjgl.glfw.GLFWCursorPosCallback;
import org.lwjgl.glfw.GLFWCursorPosCallbackI;
import org.lwjgl.glfw.GLFWKeyCallback;
import org.lwjgl.glfw.GLFWKeyCallbackI;
import org.lwjgl.glfw.GLFWMouseButtonCallback;
import org.lwjgl.glfw.GLFWMouseButtonCallbackI;
import org.lwjgl.glfw.GLFWScrollCallback;
import org.lwjgl.glfw.GLFWScrollCallbackI;
import org.lwjgl.nuklear.NkAllocator;
import org.lwjgl.nuklear.NkBuffer;
import org.lwjgl.nuklear.NkContext;
import org.lwjgl.nuklear.NkConvertConfig;
import org.lwjgl.nuklear.NkDrawCommand;
import org.lwjgl.nuklear.NkDrawNullTexture;
import org.lwjgl.nuklear.NkDrawVertexLayoutElement;
import org.lwjgl.nuklear.NkPluginAlloc;
import org.lwjgl.nuklear.NkPluginCopy;
import org.lwjgl.nuklear.NkPluginFree;
import org.lwjgl.nuklear.NkPluginPaste;
import org.lwjgl.nuklear.NkVec2;
import org.lwjgl.system.MemoryStack;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.nuklear.Nuklear.*;
import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL13.*;
import static org.lwjgl.opengl.GL14.*;
import static org.lwjgl.opengl.GL15.*;
import static org.lwjgl.opengl.GL20.*;
import static org.lwjgl.opengl.GL30.*;
import static org.lwjgl.system.MemoryUtil.*;

/**
 * The interface on LWJGL's Nuklear binding: the context, the baked font, input and drawing. The
 * screens build each frame with {@link Gui} between {@link #newFrame()} and {@link #render()}.
 *
 * <p>Input: on a GLFW window the layer installs its callbacks in front of the game's own (install
 * those first) and calls them after recording the event; the game asks {@link #wantsMouse()} and
 * {@link #wantsKeyboard()} before acting on it. Events are queued and handed to Nuklear at the
 * start of the next frame, a press and its release in different frames so that a quick click is
 * not lost. Tests feed the same queue through {@link #mouseMove}, {@link #mouseButton}, {@link #typeChar}.
 *
 * <p>Drawing: nk_convert into a vertex and an index buffer, one draw call per command with its
 * scissor, over whatever is in the framebuffer. All native memory is freed by {@link #close()}.
 */
public final class NuklearLayer implements AutoCloseable {
    private static final int VERTEX_SIZE = 20; // position 2f, uv 2f, colour 4ub
    /** Nuklear's indices are 16-bit: more vertices than this in one frame cannot be drawn. */
    private static final int MAX_VERTICES = 65536;

    private final long window;
    private final float scale;
    private final FontAtlas font;
    private final NkContext ctx = NkContext.calloc();
    private final NkAllocator allocator = NkAllocator.calloc();
    private final NkBuffer commands = NkBuffer.calloc();
    private final NkDrawNullTexture nullTexture = NkDrawNullTexture.calloc();
    private final NkDrawVertexLayoutElement.Buffer vertexLayout = NkDrawVertexLayoutElement.calloc(4);
    private final NkConvertConfig convertConfig = NkConvertConfig.calloc();
    private final ShaderProgram shader;
    private final int vao, vbo, ebo, whiteTexture;
    private ByteBuffer vertices, elements;
    private final List<AutoCloseable> natives = new ArrayList<>();
    private final ArrayDeque<Event> events = new ArrayDeque<>();

    // Chained GLFW callbacks (the game's), restored on close.
    private GLFWKeyCallback previousKey;
    private GLFWCharCallback previousChar;
    private GLFWMouseButtonCallback previousButton;
    private GLFWCursorPosCallback previousCursor;
    private GLFWScrollCallback previousScroll;

    private float displayWidth = 1, displayHeight = 1, framebufferWidth = 1, framebufferHeight = 1;
    private double mouseX = -1, mouseY = -1;
    private boolean mouseCaptured; // a button went down over the interface and is still down
    private boolean escape; // ESC since the last frame
    private final Gui.FrameResult lastFrame = new Gui.FrameResult();
    private boolean inFrame, closed, initialised;

    private record Event(int kind, double x, double y, int code, boolean down) {
        static final int MOVE = 0, BUTTON = 1, SCROLL = 2, CHAR = 3, KEY = 4;
    }

    /** With the game's font size ({@link UiFont#SIZE_PIXELS} x scale). */
    public NuklearLayer(long windowHandle, float scale) {
        this(windowHandle, scale, UiFont.SIZE_PIXELS);
    }

    /**
     * @param windowHandle the GLFW window whose input the interface reads, or 0 for none (off-screen:
     *                     input only through this class's methods, display size from {@link #setDisplaySize})
     * @param fontPixels   the font's size at scale 1 (the editor's dense panels use a smaller one)
     */
    public NuklearLayer(long windowHandle, float scale, float fontPixels) {
        this.window = windowHandle;
        this.scale = scale;
        font = FontAtlas.bake(fontPixels * scale);
        try {
            NkPluginAlloc alloc = NkPluginAlloc.create((handle, old, size) -> nmemAllocChecked(size));
            NkPluginFree free = NkPluginFree.create((handle, ptr) -> nmemFree(ptr));
            natives.add(alloc);
            natives.add(free);
            allocator.alloc(alloc).mfree(free);
            if (!nk_init(ctx, allocator, font.userFont())) throw new IllegalStateException("nk_init failed");
            initialised = true;
            nk_buffer_init(commands, allocator, 16 * 1024);
            Theme.apply(ctx, scale);
            shader = ShaderProgram.load("ui");
            whiteTexture = glGenTextures();
            glBindTexture(GL_TEXTURE_2D, whiteTexture);
            try (MemoryStack stack = MemoryStack.stackPush()) {
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, stack.bytes((byte) -1, (byte) -1, (byte) -1, (byte) -1));
            }
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glBindTexture(GL_TEXTURE_2D, 0);
            nullTexture.texture().id(whiteTexture);
            nullTexture.uv().set(0.5f, 0.5f);
            vertexLayout.position(0).attribute(NK_VERTEX_POSITION).format(NK_FORMAT_FLOAT).offset(0);
            vertexLayout.position(1).attribute(NK_VERTEX_TEXCOORD).format(NK_FORMAT_FLOAT).offset(8);
            vertexLayout.position(2).attribute(NK_VERTEX_COLOR).format(NK_FORMAT_R8G8B8A8).offset(16);
            vertexLayout.position(3).attribute(NK_VERTEX_ATTRIBUTE_COUNT).format(NK_FORMAT_COUNT).offset(0);
            vertexLayout.flip();
            convertConfig.vertex_layout(vertexLayout).vertex_size(VERTEX_SIZE).vertex_alignment(4)
                    .tex_null(nullTexture).circle_segment_count(22).curve_segment_count(22).arc_segment_count(22)
                    .global_alpha(1f).shape_AA(NK_ANTI_ALIASING_ON).line_AA(NK_ANTI_ALIASING_ON);
            vertices = memAlloc(256 * 1024);
            elements = memAlloc(64 * 1024);
            vao = glGenVertexArrays();
            vbo = glGenBuffers();
            ebo = glGenBuffers();
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glEnableVertexAttribArray(0);
            glEnableVertexAttribArray(1);
            glEnableVertexAttribArray(2);
            glVertexAttribPointer(0, 2, GL_FLOAT, false, VERTEX_SIZE, 0);
            glVertexAttribPointer(1, 2, GL_FLOAT, false, VERTEX_SIZE, 8);
            glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, true, VERTEX_SIZE, 16);
            glBindVertexArray(0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            if (window != 0) installCallbacks();
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    private static long nmemAllocChecked(long size) {
        long p = nmemAlloc(size);
        if (p == NULL) throw new OutOfMemoryError("Nuklear: " + size + " bytes");
        return p;
    }

    public NkContext context() {
        return ctx;
    }

    public FontAtlas font() {
        return font;
    }

    public float scale() {
        return scale;
    }

    /** For a layer without a window: the interface's size and the framebuffer's (pixels). */
    public void setDisplaySize(float width, float height, int fbWidth, int fbHeight) {
        displayWidth = width;
        displayHeight = height;
        framebufferWidth = fbWidth;
        framebufferHeight = fbHeight;
    }

    /** A framebuffer point (x, y) in the interface's window coordinates (they differ on high-DPI screens); null stays null. */
    public float[] toInterface(float[] framebufferPoint, int framebufferWidthNow) {
        if (framebufferPoint == null) return null;
        float k = displayWidth / Math.max(1, framebufferWidthNow);
        return new float[]{framebufferPoint[0] * k, framebufferPoint[1] * k};
    }

    public float displayWidth() {
        return displayWidth;
    }

    public float displayHeight() {
        return displayHeight;
    }

    // ---- Input ------------------------------------------------------------------------------------

    private void installCallbacks() {
        previousKey = glfwSetKeyCallback(window, (GLFWKeyCallbackI) (w, key, scancode, action, mods) -> {
            key(key, action != GLFW_RELEASE, mods);
            if (previousKey != null) previousKey.invoke(w, key, scancode, action, mods);
        });
        previousChar = glfwSetCharCallback(window, (GLFWCharCallbackI) (w, codePoint) -> {
            typeChar(codePoint);
            if (previousChar != null) previousChar.invoke(w, codePoint);
        });
        previousButton = glfwSetMouseButtonCallback(window, (GLFWMouseButtonCallbackI) (w, button, action, mods) -> {
            mouseButton(button, action == GLFW_PRESS);
            if (previousButton != null) previousButton.invoke(w, button, action, mods);
        });
        previousCursor = glfwSetCursorPosCallback(window, (GLFWCursorPosCallbackI) (w, x, y) -> {
            mouseMove(x, y);
            if (previousCursor != null) previousCursor.invoke(w, x, y);
        });
        previousScroll = glfwSetScrollCallback(window, (GLFWScrollCallbackI) (w, dx, dy) -> {
            if (overInterface(mouseX, mouseY)) events.add(new Event(Event.SCROLL, dx, dy, 0, false));
            if (previousScroll != null) previousScroll.invoke(w, dx, dy);
        });
        NkPluginCopy copy = NkPluginCopy.create((handle, text, len) -> {
            if (len <= 0) return;
            glfwSetClipboardString(window, memUTF8(text, len));
        });
        NkPluginPaste paste = NkPluginPaste.create((handle, edit) -> {
            long text = nglfwGetClipboardString(window);
            if (text != NULL) nnk_textedit_paste(edit, text, nnk_strlen(text));
        });
        natives.add(copy);
        natives.add(paste);
        ctx.clip().copy(copy).paste(paste);
    }

    /** The pointer moved to (x, y) in window coordinates. */
    public void mouseMove(double x, double y) {
        mouseX = x;
        mouseY = y;
        events.add(new Event(Event.MOVE, x, y, 0, false));
    }

    /** A mouse button (GLFW numbering) went down or up where the pointer is. */
    public void mouseButton(int glfwButton, boolean down) {
        if (down) mouseCaptured = overInterface(mouseX, mouseY);
        else mouseCaptured = false;
        events.add(new Event(Event.BUTTON, mouseX, mouseY, glfwButton, down));
    }

    /** A typed character. */
    public void typeChar(int codePoint) {
        events.add(new Event(Event.CHAR, 0, 0, codePoint, false));
    }

    /** A key (GLFW key code) went down or up, with the GLFW modifier bits. */
    public void key(int glfwKey, boolean down, int mods) {
        boolean ctrl = (mods & GLFW_MOD_CONTROL) != 0 || (mods & GLFW_MOD_SUPER) != 0;
        int nk = switch (glfwKey) {
            case GLFW_KEY_DELETE -> NK_KEY_DEL;
            case GLFW_KEY_ENTER, GLFW_KEY_KP_ENTER -> NK_KEY_ENTER;
            case GLFW_KEY_TAB -> NK_KEY_TAB;
            case GLFW_KEY_BACKSPACE -> NK_KEY_BACKSPACE;
            case GLFW_KEY_LEFT -> ctrl ? NK_KEY_TEXT_WORD_LEFT : NK_KEY_LEFT;
            case GLFW_KEY_RIGHT -> ctrl ? NK_KEY_TEXT_WORD_RIGHT : NK_KEY_RIGHT;
            case GLFW_KEY_HOME -> NK_KEY_TEXT_LINE_START;
            case GLFW_KEY_END -> NK_KEY_TEXT_LINE_END;
            case GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT -> NK_KEY_SHIFT;
            case GLFW_KEY_C -> ctrl ? NK_KEY_COPY : NK_KEY_NONE;
            case GLFW_KEY_V -> ctrl ? NK_KEY_PASTE : NK_KEY_NONE;
            case GLFW_KEY_X -> ctrl ? NK_KEY_CUT : NK_KEY_NONE;
            case GLFW_KEY_A -> ctrl ? NK_KEY_TEXT_SELECT_ALL : NK_KEY_NONE;
            case GLFW_KEY_Z -> ctrl ? NK_KEY_TEXT_UNDO : NK_KEY_NONE;
            default -> NK_KEY_NONE;
        };
        if (nk != NK_KEY_NONE) events.add(new Event(Event.KEY, 0, 0, nk, down));
        if (glfwKey == GLFW_KEY_ESCAPE && down) escape = true; // ends a text field's edit, as in ImGui
    }

    /** Whether the point (window coordinates) is on a window, menu or list the last frame drew. */
    public boolean overInterface(double x, double y) {
        for (float[] r : lastFrame.rects) {
            if (x >= r[0] && y >= r[1] && x < r[0] + r[2] && y < r[1] + r[3]) return true;
        }
        return false;
    }

    /** The last frame's windows and open pop-ups as {x, y, w, h} (for tests). */
    java.util.List<float[]> interfaceRects() {
        return java.util.List.copyOf(lastFrame.rects);
    }

    /** The interface takes the mouse: the pointer is over it, or a drag began on it. */
    public boolean wantsMouse() {
        return mouseCaptured || overInterface(mouseX, mouseY);
    }

    /**
     * The interface takes the keyboard only while a text field is being edited, so that ESC,
     * Ctrl+Z and Ctrl+S reach the game and the editor after typing in a panel.
     */
    public boolean wantsKeyboard() {
        return lastFrame.textFieldActive;
    }

    private void feedInput() {
        boolean[] pressedNow = new boolean[8];
        try (MemoryStack stack = MemoryStack.stackPush()) {
            while (!events.isEmpty()) {
                Event e = events.peek();
                if (e.kind == Event.BUTTON) {
                    int b = Math.min(e.code, 7);
                    // A release right after its press waits for the next frame: a click needs both.
                    if (!e.down && pressedNow[b]) break;
                    if (e.down) pressedNow[b] = true;
                }
                events.poll();
                switch (e.kind) {
                    case Event.MOVE -> nk_input_motion(ctx, (int) e.x, (int) e.y);
                    case Event.BUTTON -> {
                        int nkButton = e.code == GLFW_MOUSE_BUTTON_RIGHT ? NK_BUTTON_RIGHT
                                : e.code == GLFW_MOUSE_BUTTON_MIDDLE ? NK_BUTTON_MIDDLE : NK_BUTTON_LEFT;
                        nk_input_button(ctx, nkButton, (int) e.x, (int) e.y, e.down);
                    }
                    case Event.SCROLL -> nk_input_scroll(ctx, NkVec2.malloc(stack).set((float) e.x, (float) e.y));
                    case Event.CHAR -> nk_input_unicode(ctx, e.code);
                    case Event.KEY -> nk_input_key(ctx, e.code, e.down);
                    default -> {
                    }
                }
            }
        }
    }

    // ---- Frames -----------------------------------------------------------------------------------

    /** Starts a frame: the queued input goes to Nuklear, {@link Gui} draws into this layer. */
    public void newFrame() {
        if (window != 0) {
            try (MemoryStack stack = MemoryStack.stackPush()) {
                var w = stack.mallocInt(1);
                var h = stack.mallocInt(1);
                glfwGetWindowSize(window, w, h);
                displayWidth = Math.max(1, w.get(0));
                displayHeight = Math.max(1, h.get(0));
                glfwGetFramebufferSize(window, w, h);
                framebufferWidth = Math.max(1, w.get(0));
                framebufferHeight = Math.max(1, h.get(0));
            }
        }
        nk_input_begin(ctx);
        feedInput();
        nk_input_end(ctx);
        inFrame = true;
        Gui.beginFrame(this, escape);
        escape = false;
    }

    /** Draws what the frame built over whatever is in the framebuffer, then clears it for the next. */
    public void render() {
        if (!inFrame) throw new IllegalStateException("render() without newFrame()");
        inFrame = false;
        Gui.endFrame(lastFrame);
        draw();
        nk_clear(ctx);
    }

    private void draw() {
        int[] lastProgram = {glGetInteger(GL_CURRENT_PROGRAM)};
        boolean blend = glIsEnabled(GL_BLEND), depth = glIsEnabled(GL_DEPTH_TEST), cull = glIsEnabled(GL_CULL_FACE),
                scissor = glIsEnabled(GL_SCISSOR_TEST);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_SCISSOR_TEST);
        glActiveTexture(GL_TEXTURE0);
        glViewport(0, 0, (int) framebufferWidth, (int) framebufferHeight);
        shader.use();
        shader.set("uTexture", 0);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            glUniformMatrix4fv(shader.location("uProjection"), false, stack.floats(
                    2f / displayWidth, 0, 0, 0,
                    0, -2f / displayHeight, 0, 0,
                    0, 0, -1, 0,
                    -1, 1, 0, 1));
            long[] used = convert(stack);
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, memSlice(vertices, 0, (int) used[0]), GL_STREAM_DRAW);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, memSlice(elements, 0, (int) used[1]), GL_STREAM_DRAW);
            float sx = framebufferWidth / displayWidth, sy = framebufferHeight / displayHeight;
            long offset = 0;
            for (NkDrawCommand cmd = nk__draw_begin(ctx, commands); cmd != null; cmd = nk__draw_next(cmd, commands, ctx)) {
                if (cmd.elem_count() == 0) continue;
                glBindTexture(GL_TEXTURE_2D, cmd.texture().id());
                var clip = cmd.clip_rect();
                int x0 = (int) Math.max(0, clip.x() * sx), y0 = (int) Math.max(0, clip.y() * sy);
                int x1 = (int) Math.min(framebufferWidth, (clip.x() + clip.w()) * sx);
                int y1 = (int) Math.min(framebufferHeight, (clip.y() + clip.h()) * sy);
                if (x1 > x0 && y1 > y0) {
                    glScissor(x0, (int) framebufferHeight - y1, x1 - x0, y1 - y0);
                    glDrawElements(GL_TRIANGLES, cmd.elem_count(), GL_UNSIGNED_SHORT, offset);
                }
                offset += cmd.elem_count() * 2L;
            }
        }
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        glBindTexture(GL_TEXTURE_2D, 0);
        glUseProgram(lastProgram[0]);
        if (!blend) glDisable(GL_BLEND);
        if (depth) glEnable(GL_DEPTH_TEST);
        if (cull) glEnable(GL_CULL_FACE);
        if (!scissor) glDisable(GL_SCISSOR_TEST);
    }

    /** nk_convert into the vertex and index memory, growing it while it is too small; returns the bytes used. */
    private long[] convert(MemoryStack stack) {
        for (int attempt = 0; ; attempt++) {
            NkBuffer vbuf = NkBuffer.malloc(stack), ebuf = NkBuffer.malloc(stack);
            nk_buffer_init_fixed(vbuf, vertices);
            nk_buffer_init_fixed(ebuf, elements);
            nk_buffer_clear(commands);
            int result = nk_convert(ctx, commands, vbuf, ebuf, convertConfig);
            boolean vertexFull = (result & NK_CONVERT_VERTEX_BUFFER_FULL) != 0;
            boolean elementFull = (result & NK_CONVERT_ELEMENT_BUFFER_FULL) != 0;
            if ((!vertexFull && !elementFull) || attempt >= 4 || vertices.capacity() >= MAX_VERTICES * VERTEX_SIZE) {
                return new long[]{Math.min(vbuf.allocated(), vertices.capacity()), Math.min(ebuf.allocated(), elements.capacity())};
            }
            if (vertexFull) vertices = memRealloc(vertices, vertices.capacity() * 2);
            if (elementFull) elements = memRealloc(elements, elements.capacity() * 2);
        }
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        if (window != 0) {
            // The game's callbacks again (ours are freed below).
            freeCallback(glfwSetKeyCallback(window, previousKey));
            freeCallback(glfwSetCharCallback(window, previousChar));
            freeCallback(glfwSetMouseButtonCallback(window, previousButton));
            freeCallback(glfwSetCursorPosCallback(window, previousCursor));
            freeCallback(glfwSetScrollCallback(window, previousScroll));
        }
        Gui.detach(this);
        if (initialised) nk_free(ctx);
        nk_buffer_free(commands);
        for (AutoCloseable c : natives) {
            try {
                c.close();
            } catch (Exception ignored) {
                // callbacks' close does not throw
            }
        }
        if (shader != null) shader.close();
        if (vao != 0) glDeleteVertexArrays(vao);
        if (vbo != 0) glDeleteBuffers(vbo);
        if (ebo != 0) glDeleteBuffers(ebo);
        if (whiteTexture != 0) glDeleteTextures(whiteTexture);
        if (vertices != null) memFree(vertices);
        if (elements != null) memFree(elements);
        font.close();
        convertConfig.free();
        vertexLayout.free();
        nullTexture.free();
        commands.free();
        allocator.free();
        ctx.free();
    }

    private static void freeCallback(org.lwjgl.system.Callback c) {
        if (c != null) c.free();
    }
}
