package minigolf.render;

/**
 * No OpenGL context can be had on this machine (no display for a window, and no display-less EGL
 * either): a fact about the machine, not a bug, so the command line reports it in one line with exit 2.
 */
public final class NoOpenGlException extends RenderException {
    public NoOpenGlException(String message) {
        super(message);
    }
}
