package minigolf.render;

/**
 * What runs inside a window (lwjglbook's app-logic interface): the game and the editor each
 * implement it, and {@link WindowLoop} drives both with the same loop.
 */
public interface WindowApp {
    /**
     * One pass's work before drawing: input already polled, {@code elapsed} seconds since the last
     * pass (at most a quarter of a second), {@code now} the loop's clock in seconds. Runs on every
     * pass, also while the window is minimised and nothing is drawn, so play goes on.
     */
    void update(double elapsed, double now);

    /** Draws a frame into the framebuffer of {@code width} x {@code height} pixels; {@code time} in seconds since the loop began. */
    void render(int width, int height, float time);

    /**
     * Asked after each drawn frame, before it is shown: true ends the loop (a scripted run that has
     * drawn what it was asked for); that frame is still saved as the screenshot and shown.
     */
    default boolean finished(int framesDrawn) {
        return false;
    }

    /** The shortest time a frame may take, in seconds (a frame limit without vsync), or 0 for none. */
    default double minFrameSeconds() {
        return 0;
    }
}
