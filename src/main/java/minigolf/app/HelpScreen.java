package minigolf.app;

import minigolf.ui.CameraDrag;
import minigolf.ui.Gui;
import minigolf.ui.GuiTableFlags;
import minigolf.ui.Panels;
import minigolf.ui.Screen;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/** How to play and the controls (F1 anywhere); ESC, F1 or Back returns to where it was opened. */
final class HelpScreen extends GameScreen {
    static final String[][] CONTROLS = {
            {"Aim and hit", "press on your ball, drag back away from where it should go, release"},
            {"Cancel an aim", "right click while dragging"},
            {"Power", "the longer the drag, the harder the putt (the bar shows it)"},
            {"Chip (loft)", "mouse wheel while dragging, or Up / Down: 0 (putt) to 60 degrees, shown in the HUD"},
            {CameraDrag.HELP[0][0], CameraDrag.HELP[0][1] + ", or left-drag away from the ball"},
            CameraDrag.HELP[1],
            CameraDrag.HELP[2],
            {"Reset the camera", "R"},
            {"Skip the rolling ball", "SPACE"},
            {"Height colours", "H"},
            {"Practice mode (type a shot's velocity, the ball's physics)", "V"},
            {"Pause / back", "ESC"},
            {"Full screen", "F11"},
            {"This help", "F1"},
    };

    private Screen back;

    HelpScreen(GameApp app) {
        super(app);
    }

    /** Opened from {@code from}, where it goes back to. */
    void open(Screen from) {
        back = from;
    }

    void close() {
        app.setScreen(back != null ? back : app.screens().mainMenu());
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.begin("Help###help", Panels.PANEL);
        Panels.heading("How to play");
        Gui.text("Get the ball in the cup in as few strokes as you can. Par is what a good player needs.");
        Gui.text("Water or out of bounds: one penalty stroke, the ball goes back to where the stroke began.");
        Gui.text("A ball that rolls slowly enough over the cup drops in.");
        Gui.separator();
        if (Gui.beginTable("##controls", 2, GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) {
            for (String[] c : CONTROLS) {
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.textColored(0.6f, 0.9f, 1f, 1f, c[0]);
                Gui.tableSetColumnIndex(1);
                Gui.text(c[1]);
            }
            Gui.endTable();
        }
        if (Gui.button("Back", 160, 0)) close();
        Gui.end();
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        close();
        return true;
    }
}
