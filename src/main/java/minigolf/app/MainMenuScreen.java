package minigolf.app;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import minigolf.game.BotCatalog;
import minigolf.game.Player;
import minigolf.game.SavedGameSummary;
import minigolf.ui.Gui;
import minigolf.ui.GuiInt;
import minigolf.ui.Panels;

/** The main menu: play, choose a round or a hole, watch a bot, create a course, load a saved game, settings, help, quit. */
final class MainMenuScreen extends GameScreen {
    private final GuiInt testBot = new GuiInt(Math.max(0, BotCatalog.levels().indexOf(BotCatalog.DEFAULT_OPPONENT)));

    MainMenuScreen(GameApp app) {
        super(app);
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.begin("Minigolf", Panels.PANEL);
        var round = app.play().chosenRound();
        Gui.text(round != null ? "Round: " + round.name() + " (" + round.size() + " holes, par " + round.par() + ")"
                : "Course: " + app.play().world().course().name());
        Gui.separator();
        float bw = 300, bh = 0;
        if (Gui.button("Play", bw, bh)) app.setScreen(app.screens().newGame());
        if (Gui.button("Play online", bw, bh)) app.setScreen(app.screens().online());
        if (Gui.button("Rounds and practice holes", bw, bh)) app.setScreen(app.screens().courseSelect());
        // Watch an opponent play the hole alone: the levels; in practice mode every bot by its algorithm's name.
        List<String> botNames = app.settings().practice() ? BotCatalog.names() : BotCatalog.levels();
        if (Gui.button("Watch a computer player", bw, bh) && !botNames.isEmpty()) {
            String bot = botNames.get(Math.min(testBot.get(), botNames.size() - 1));
            String name = "Bot (" + BotCatalog.label(bot) + ")";
            app.startGame(List.of(Player.bot(name, bot)));
            app.setScreen(app.screens().testBot());
            app.say("Watching " + name + " play; ESC stops");
        }
        Gui.sameLine();
        Gui.setNextItemWidth(120);
        Gui.combo("##testbot", testBot, botNames.stream().map(BotCatalog::label).toArray(String[]::new));
        if (Gui.button("Create course", bw, bh)) app.createCourse();
        List<Path> saved = app.savedGames();
        if (!saved.isEmpty()) {
            Gui.setNextItemWidth(bw); // as wide as the buttons
            if (Gui.beginMenu("Load saved game")) {
                // Newest first, by round or course, players and date (the file names are only timestamps).
                List<Path> saves = new ArrayList<>(saved);
                Collections.reverse(saves);
                for (Path p : saves) {
                    if (Gui.menuItem(SavedGameSummary.cached(p).label() + "##" + p)) app.loadGame(p);
                }
                Gui.endMenu();
            }
        }
        if (Gui.button("Settings", bw, bh)) app.openSettings();
        if (Gui.button("Help (F1)", bw, bh)) app.openHelp();
        if (Gui.button("Quit", bw, bh)) app.quit();
        Gui.end();
    }
}
