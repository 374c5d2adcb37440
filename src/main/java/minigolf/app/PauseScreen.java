package minigolf.app;

import minigolf.game.RoundGame;
import minigolf.ui.Gui;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/** The game paused (ESC): resume, watch a finished hole of the round again, save, settings, main menu, quit. */
final class PauseScreen extends GameScreen {
    PauseScreen(GameApp app) {
        super(app);
    }

    @Override
    public void render(float w, float h) {
        nameTags();
        app.hud().render(w, h, -1, 0);
        Panels.centre(w, h);
        Gui.begin("Paused", Panels.PANEL);
        float bw = 240;
        if (Gui.button("Resume", bw, 0)) app.setScreen(app.screens().playing());
        watchHoles(app, app.play().round());
        if (Gui.button("Save game", bw, 0)) app.saveGame();
        if (Gui.button("Settings", bw, 0)) app.openSettings();
        if (Gui.button("Main menu", bw, 0)) app.toMainMenu();
        if (Gui.button("Quit", bw, 0)) app.quit();
        Gui.end();
    }

    /** "Watch hole: 1 2 3 ...": any finished hole of the round again, as played (nothing for a single course). */
    static void watchHoles(GameApp app, RoundGame round) {
        if (round == null || round.holesFinished() == 0) return;
        Gui.text("Watch hole:");
        for (int hole = 0; hole < round.holesFinished(); hole++) {
            if (round.holeStrokes(hole).isEmpty()) continue;
            if (hole % 9 != 0) Gui.sameLine();
            if (Gui.button((hole + 1) + "##watch", 24, 0)) app.watchHole(hole);
        }
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().playing());
        return true;
    }
}
