package minigolf.ui;

/**
 * One screen of a window, in the manner of libGDX's {@code Screen}: it keeps its own state (a
 * form's fields, where to go back to), builds its interface on {@link Gui} every frame and takes
 * the input meant for it. A {@link ScreenHost} shows one screen at a time. Input reaches a screen
 * only where the interface did not take it (a click on a panel, typing in a field).
 */
public interface Screen {
    /** Becomes the screen shown. */
    default void show() {
    }

    /** The screen's work for one pass of the loop, drawn or not (play goes on while minimised); seconds since the last pass. */
    default void update(double elapsed) {
    }

    /** Builds this frame's interface; {@code width} and {@code height} in interface pixels. */
    void render(float width, float height);

    /** The window's framebuffer is now {@code width} x {@code height} pixels. */
    default void resize(int width, int height) {
    }

    /** Stops being the screen shown. */
    default void hide() {
    }

    /** The window closes: frees what the screen holds. */
    default void dispose() {
    }

    /** A key pressed outside text fields (GLFW key and modifiers); true when the screen used it. */
    default boolean keyPressed(int key, int mods) {
        return false;
    }

    /** A mouse button pressed or released away from the interface's panels (window coordinates); true when used. */
    default boolean mouseButton(int button, boolean down, int mods, double x, double y) {
        return false;
    }

    /** The cursor moved (window coordinates); true when the screen used it (e.g. an aim being dragged). */
    default boolean cursorMoved(double x, double y) {
        return false;
    }

    /** The wheel turned away from the panels; true when used. */
    default boolean scrolled(double dy) {
        return false;
    }
}
