package minigolf.app;

import java.util.ArrayList;
import java.util.List;
import minigolf.game.BotCatalog;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerKind;
import minigolf.ui.Gui;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/** Setting up a game: how many players, each one's name, person or bot; "Tee off" starts the chosen course or round. */
final class NewGameScreen extends GameScreen {
    private static final String[] KINDS = {"Human", "Bot"};
    private final int[] playerCount = {2};
    private final GuiString[] names = new GuiString[Game.MAX_PLAYERS];
    private final GuiInt[] kinds = new GuiInt[Game.MAX_PLAYERS];
    private final GuiInt[] bots = new GuiInt[Game.MAX_PLAYERS];
    private String formError;

    NewGameScreen(GameApp app) {
        super(app);
        for (int i = 0; i < Game.MAX_PLAYERS; i++) {
            names[i] = new GuiString("Player " + (i + 1), Player.MAX_NAME_LENGTH);
            kinds[i] = new GuiInt(0);
            bots[i] = new GuiInt(Math.max(0, BotCatalog.names().indexOf(BotCatalog.DEFAULT_OPPONENT))); // medium
        }
    }

    @Override
    public void show() {
        formError = null;
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        var round = app.play().chosenRound();
        Gui.begin("New game: " + (round != null ? round.name() : app.play().world().course().name()) + "###newgame", Panels.PANEL);
        Gui.sliderInt("Players", playerCount, 1, Game.MAX_PLAYERS);
        List<String> botNames = BotCatalog.names();
        for (int i = 0; i < playerCount[0]; i++) {
            Gui.pushID(i);
            Gui.setNextItemWidth(200);
            Gui.inputText("##name", names[i]);
            Gui.sameLine();
            Gui.setNextItemWidth(100);
            Gui.combo("##kind", kinds[i], KINDS);
            if (kinds[i].get() == 1) {
                Gui.sameLine();
                Gui.setNextItemWidth(120);
                Gui.combo("##bot", bots[i], botNames.stream().map(BotCatalog::label).toArray(String[]::new));
            }
            Gui.popID();
        }
        int limit = app.settings().strokeLimit();
        Gui.text("Stroke limit: " + limit + " (pick up and score " + (limit + 1) + "; change it in Settings)");
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (Gui.button("Tee off")) teeOff(botNames);
        Gui.sameLine();
        if (Gui.button("Back")) app.setScreen(app.screens().mainMenu());
        Gui.end();
    }

    private void teeOff(List<String> botNames) {
        try {
            List<Player> players = new ArrayList<>();
            for (int i = 0; i < playerCount[0]; i++) {
                String n = names[i].get().trim();
                if (kinds[i].get() == 1 && !botNames.isEmpty()) {
                    players.add(Player.bot(n, botNames.get(Math.min(bots[i].get(), botNames.size() - 1))));
                } else {
                    players.add(new Player(n, PlayerKind.HUMAN, null));
                }
            }
            formError = null;
            app.startGame(players);
        } catch (IllegalArgumentException e) {
            formError = e.getMessage();
        }
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().mainMenu());
        return true;
    }
}
