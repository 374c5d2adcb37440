package minigolf.app;

import minigolf.game.Game;
import minigolf.game.ScoreLine;
import minigolf.ui.Gui;
import minigolf.ui.GuiTableFlags;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/** A single game's scorecard at the left, the course turning beside it: watch again, play again, main menu. */
final class ScorecardScreen extends GameScreen {
    ScorecardScreen(GameApp app) {
        super(app);
    }

    @Override
    public void render(float w, float h) {
        Panels.leftOfCourse(w, h);
        Gui.begin("Scorecard: " + app.play().world().course().name(), Panels.PANEL);
        Game g = app.play().game();
        if (g != null && Gui.beginTable("score", 6, GuiTableFlags.Borders | GuiTableFlags.RowBg)) {
            for (String c : new String[]{"Rank", "Player", "Strokes", "Penalties", "Score", ""}) Gui.tableSetupColumn(c);
            Gui.tableHeadersRow();
            for (ScoreLine l : g.scorecard().ranked()) {
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.text(String.valueOf(l.rank()));
                Gui.tableSetColumnIndex(1);
                Gui.text(l.name());
                Gui.tableSetColumnIndex(2);
                Gui.text(String.valueOf(l.strokes()));
                Gui.tableSetColumnIndex(3);
                Gui.text(String.valueOf(l.penalties()));
                Gui.tableSetColumnIndex(4);
                Gui.text(String.valueOf(l.score()));
                Gui.tableSetColumnIndex(5);
                Gui.text(Hud.words(l.status()));
            }
            Gui.endTable();
        }
        if (Gui.button("Watch again")) app.watchReplay();
        Gui.sameLine();
        if (Gui.button("Play again")) app.setScreen(app.screens().newGame());
        Gui.sameLine();
        if (Gui.button("Main menu")) app.toMainMenu();
        Gui.end();
    }

    @Override
    void directCamera(CourseScene scene, float dt, float aspect) {
        scene.overview(dt, aspect);
    }

    @Override
    boolean showsFinalCard() {
        return true;
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().mainMenu());
        return true;
    }
}
