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

/**
 * Setting up a game: how many players, each one's name, person or computer opponent, and an
 * opponent's level (Easy, Medium, Hard, Pro; Medium first); "Tee off" starts the chosen course or
 * round. In practice mode every bot is offered by its algorithm's name too.
 */
final class NewGameScreen extends GameScreen {
    private static final String[] KINDS = {"Person", "Computer"};
    private static final float NAME_WIDTH = 200, KIND_WIDTH = 100, BOT_LIST_WIDTH = 120;
    private final int[] playerCount = {2};
    private final GuiString[] names = new GuiString[Game.MAX_PLAYERS];
    private final GuiInt[] kinds = new GuiInt[Game.MAX_PLAYERS];
    private final GuiInt[] bots = new GuiInt[Game.MAX_PLAYERS];
    private String formError;
    private float[] lastRect;
    private boolean filled;

    NewGameScreen(GameApp app) {
        super(app);
        for (int i = 0; i < Game.MAX_PLAYERS; i++) {
            names[i] = new GuiString("Player " + (i + 1), Player.MAX_NAME_LENGTH);
            kinds[i] = new GuiInt(0);
            bots[i] = new GuiInt(Math.max(0, BotCatalog.names().indexOf(BotCatalog.DEFAULT_OPPONENT))); // medium
        }
    }

    /** The first time, fills the names from the settings (those typed the last time the game ran). */
    @Override
    public void show() {
        formError = null;
        if (filled) return;
        filled = true;
        List<String> kept = app.settings().playerNames();
        for (int i = 0; i < Math.min(kept.size(), names.length); i++) names[i].set(kept.get(i));
    }

    /** Types {@code text} into seat {@code seat}'s name field (tests). */
    void typeName(int seat, String text) {
        names[seat].set(text);
    }

    /** Sets the "Players" slider (tests, the README's screenshot). */
    void players(int count) {
        playerCount[0] = Math.max(1, Math.min(Game.MAX_PLAYERS, count));
    }

    /** Where the form stood in the last frame: x, y, width, height (tests). */
    float[] lastRect() {
        return lastRect;
    }

    String name(int seat) {
        return names[seat].get();
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        var round = app.play().chosenRound();
        List<String> botNames = opponents();
        String[] labels = botNames.stream().map(BotCatalog::label).toArray(String[]::new);
        // As wide as a computer seat's row from the start: choosing "Computer" must not move "Tee off"
        // from under the mouse (the panel grew and re-centred).
        float row = NAME_WIDTH + KIND_WIDTH + 2 * Gui.itemSpacingX();
        if (!app.settings().practice()) for (String l : labels) row += Gui.radioButtonWidth(l) + Gui.itemSpacingX();
        else row += BOT_LIST_WIDTH + Gui.itemSpacingX();
        Gui.setNextWindowSizeConstraints(row + 2 * Gui.textLineHeight(), 0, Float.MAX_VALUE, Float.MAX_VALUE);
        Gui.begin("New game: " + (round != null ? round.name() : app.play().world().course().name()) + "###newgame", Panels.PANEL);
        lastRect = Gui.windowRect();
        Gui.sliderInt("Players", playerCount, 1, Game.MAX_PLAYERS);
        for (int i = 0; i < playerCount[0]; i++) {
            Gui.pushID(i);
            Gui.setNextItemWidth(NAME_WIDTH);
            Gui.inputText("##name", names[i]);
            Gui.sameLine();
            Gui.setNextItemWidth(KIND_WIDTH);
            Gui.combo("##kind", kinds[i], KINDS);
            if (kinds[i].get() == 1 && app.settings().practice()) {
                Gui.sameLine();
                Gui.setNextItemWidth(BOT_LIST_WIDTH);
                Gui.combo("##bot", bots[i], labels);
            } else if (kinds[i].get() == 1) {
                // Four levels side by side: a player sees every choice without opening a list.
                for (int l = 0; l < labels.length; l++) {
                    Gui.sameLine();
                    if (Gui.radioButton(labels[l], bots[i].get() == l)) bots[i].set(l);
                }
            }
            Gui.popID();
            followKind(i, labels);
        }
        int limit = app.settings().strokeLimit();
        Gui.text("Stroke limit: " + limit + " (pick up and score " + (limit + 1) + "; change it in Settings)");
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (Gui.button("Tee off")) teeOff(botNames);
        Gui.sameLine();
        if (Gui.button("Back")) app.setScreen(app.screens().mainMenu());
        Gui.end();
    }

    /**
     * A seat's name that was never typed follows its kind: "Player 3" becomes "Bot (Hard)" when the
     * seat is made a computer opponent of level Hard, and follows the level; back to "Player 3" for a person.
     */
    private void followKind(int seat, String[] labels) {
        String n = names[seat].get().trim(), own = "Player " + (seat + 1);
        boolean automatic = n.equals(own);
        for (String l : labels) automatic |= n.equals("Bot (" + l + ")");
        if (!automatic) return;
        boolean computer = kinds[seat].get() == 1 && labels.length > 0;
        names[seat].set(computer ? "Bot (" + labels[Math.min(bots[seat].get(), labels.length - 1)] + ")" : own);
    }

    /** The opponents offered: the levels; in practice mode every bot after them. */
    List<String> opponents() {
        return app.settings().practice() ? BotCatalog.names() : BotCatalog.levels();
    }

    /** Makes seat {@code seat} a computer opponent of the level or bot {@code name} (tests). */
    void chooseOpponent(int seat, String name) {
        kinds[seat].set(1);
        bots[seat].set(opponents().indexOf(name));
        followKind(seat, opponents().stream().map(BotCatalog::label).toArray(String[]::new));
    }

    /** What "Tee off" does: the players from the form, their names kept for next time, the game started. */
    void teeOff() {
        teeOff(opponents());
    }

    private void teeOff(List<String> botNames) {
        try {
            List<Player> players = new ArrayList<>();
            for (int i = 0; i < playerCount[0]; i++) {
                String n = names[i].get().trim();
                if (kinds[i].get() == 1 && !botNames.isEmpty()) {
                    String bot = botNames.get(Math.min(bots[i].get(), botNames.size() - 1));
                    // A computer seat still called "Player 2" is named after its level: "Bot (Medium)".
                    if (n.equals("Player " + (i + 1))) n = "Bot (" + BotCatalog.label(bot) + ")";
                    players.add(Player.bot(n, bot));
                } else {
                    players.add(new Player(n, PlayerKind.HUMAN, null));
                }
            }
            formError = null;
            List<String> typed = new ArrayList<>();
            for (GuiString n : names) typed.add(n.get().trim().isEmpty() ? "Player " + (typed.size() + 1) : n.get().trim());
            app.rememberPlayerNames(typed);
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
