package minigolf.render;

/** Something in the rendering stack could not be set up: GLFW, the GL context, a shader, a framebuffer. */
public class RenderException extends RuntimeException {
    public RenderException(String message) {
        super(message);
    }

    public RenderException(String message, Throwable cause) {
        super(message, cause);
    }
}
