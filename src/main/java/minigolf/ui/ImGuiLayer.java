package minigolf.ui;

import imgui.ImGui;
import imgui.ImGuiIO;
import imgui.flag.ImGuiConfigFlags;
import imgui.gl3.ImGuiImplGl3;
import imgui.glfw.ImGuiImplGlfw;

/**
 * Dear ImGui on a GLFW window (imgui-java 1.88.0). Install the game's own GLFW callbacks before
 * creating this layer: ImGui's GLFW backend then chains to them, and the game asks
 * {@link #wantsMouse()} / {@link #wantsKeyboard()} before acting on an event. The ini file is off
 * (the layout is code's, and the config folder stays clean).
 */
public final class ImGuiLayer implements AutoCloseable {
    private final ImGuiImplGlfw glfw = new ImGuiImplGlfw();
    private final ImGuiImplGl3 gl3 = new ImGuiImplGl3();
    private boolean closed;

    /** With the game's font size ({@link UiFont#SIZE_PIXELS} x scale). */
    public ImGuiLayer(long windowHandle, float scale) {
        this(windowHandle, scale, UiFont.SIZE_PIXELS);
    }

    /** With the bundled font at {@code fontPixels} x scale (the editor's dense panels use a smaller size). */
    public ImGuiLayer(long windowHandle, float scale, float fontPixels) {
        ImGui.createContext();
        ImGuiIO io = ImGui.getIO();
        io.setIniFilename(null);
        io.addConfigFlags(ImGuiConfigFlags.NavEnableKeyboard);
        UiFont.addTo(io.getFonts(), fontPixels * scale); // rasterised at its size: no global scale, no blur
        Theme.apply(scale);
        glfw.init(windowHandle, true);
        gl3.init("#version 330 core");
    }

    /** Starts a frame: the GL backend first (it builds the font atlas), then GLFW, then ImGui. */
    public void newFrame() {
        gl3.newFrame();
        glfw.newFrame();
        ImGui.newFrame();
    }

    /** Draws what the frame's ImGui calls built, over whatever is in the framebuffer. */
    public void render() {
        ImGui.render();
        gl3.renderDrawData(ImGui.getDrawData());
    }

    public boolean wantsMouse() {
        return ImGui.getIO().getWantCaptureMouse();
    }

    /**
     * Whether ImGui takes the keyboard: only while a text field is being edited. (Its own
     * WantCaptureKeyboard stays true as long as a panel has keyboard-navigation focus, so after
     * typing in a field the game's and the editor's shortcuts, ESC, Ctrl+Z, Ctrl+S, were dead until
     * the 3D view was clicked.)
     */
    public boolean wantsKeyboard() {
        return ImGui.getIO().getWantTextInput();
    }

    @Override
    public void close() {
        if (closed) return;
        closed = true;
        gl3.shutdown();
        try {
            glfw.shutdown();
        } catch (NullPointerException e) {
            // imgui-java 1.88 destroys every mouse cursor, also those the X server could not make
            // (null under Xvfb); the window and its callbacks are freed with the window anyway.
        }
        ImGui.destroyContext();
    }
}
