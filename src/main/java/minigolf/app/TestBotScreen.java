package minigolf.app;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/** Watching a bot play the chosen course alone ("Test bot"): the HUD without the Shot panel; ESC stops and goes back to the menu. */
final class TestBotScreen extends PlayingScreen {
    TestBotScreen(GameApp app) {
        super(app);
    }

    @Override
    boolean interactive() {
        return false;
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key == GLFW_KEY_ESCAPE) {
            app.toMainMenu();
            return true;
        }
        return super.keyPressed(key, mods); // Up / Down, SPACE
    }
}
