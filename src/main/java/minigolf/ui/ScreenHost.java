package minigolf.ui;

import java.util.Objects;

/**
 * Shows one {@link Screen} at a time (libGDX's {@code Game.setScreen}): the old screen is hidden,
 * the new one shown and told the window's size. Input and frames go to the screen shown.
 */
public final class ScreenHost {
    private Screen current;
    private int width, height;

    public ScreenHost(Screen first) {
        current = Objects.requireNonNull(first);
    }

    public Screen current() {
        return current;
    }

    /** Switches to {@code next} (nothing happens when it is already shown). */
    public void setScreen(Screen next) {
        Objects.requireNonNull(next);
        if (next == current) return;
        current.hide();
        current = next;
        next.show();
        if (width > 0 && height > 0) next.resize(width, height);
    }

    /** The framebuffer's size: the screen shown hears of a change at once, the next ones when they are shown. */
    public void resize(int width, int height) {
        if (width == this.width && height == this.height) return;
        this.width = width;
        this.height = height;
        current.resize(width, height);
    }
}
