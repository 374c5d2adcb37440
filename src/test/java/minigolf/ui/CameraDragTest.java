package minigolf.ui;

import static minigolf.ui.CameraDrag.*;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.glfw.GLFW.*;

import org.junit.jupiter.api.Test;

/** One camera scheme for the game and the editor, every part of it reachable without a middle button. */
class CameraDragTest {
    @Test
    void theButtonsAreGlfwsAndMapAsDocumented() {
        assertEquals(GLFW_MOUSE_BUTTON_LEFT, LEFT);
        assertEquals(GLFW_MOUSE_BUTTON_RIGHT, RIGHT);
        assertEquals(GLFW_MOUSE_BUTTON_MIDDLE, MIDDLE);
        assertEquals(GLFW_MOD_SHIFT, SHIFT);
        assertEquals(GLFW_MOD_CONTROL, CONTROL);

        assertEquals(ROTATE, of(RIGHT, 0));
        assertEquals(PAN, of(RIGHT, SHIFT));
        assertEquals(PAN, of(MIDDLE, 0));
        assertEquals(NONE, of(LEFT, 0), "a plain left press is the action (aim, tool)");
        assertEquals(NONE, of(LEFT, SHIFT), "the editor's Shift + click stays the tool's");
        // A touchpad: one-finger drag with Ctrl, and a two-finger click (the right button).
        assertEquals(ROTATE, of(LEFT, CONTROL));
        assertEquals(PAN, of(LEFT, CONTROL | SHIFT));
        assertEquals(3, HELP.length);
    }
}
