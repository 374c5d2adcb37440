package minigolf.ui;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.game.BotCatalog;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerKind;
import minigolf.game.ScoreLine;

/**
 * The screens (on {@link Gui}): main menu, course choice, new game, pause menu, scorecards, help;
 * the HUD and the settings screen are classes of their own ({@link Hud}, {@link SettingsScreen}).
 */
public final class Screens {
    static final int PANEL = GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize
            | GuiWindowFlags.AlwaysAutoResize;
    private static final String[] KINDS = {"Human", "Bot"};

    final UiActions actions;
    private final SettingsScreen settingsScreen = new SettingsScreen(this);
    private final Hud hud = new Hud(this);
    private Screen screen = Screen.MAIN_MENU;

    // New-game form.
    private final int[] playerCount = {2};
    private final GuiString[] names = new GuiString[Game.MAX_PLAYERS];
    private final GuiInt[] kinds = new GuiInt[Game.MAX_PLAYERS];
    private final GuiInt[] bots = new GuiInt[Game.MAX_PLAYERS];
    // Typed shot.
    // Settings form.
    private final GuiInt testBot = new GuiInt(0);
    /** The HUD's physics readout (position, velocity, acceleration, slope, friction): off unless asked for. */
    String formError;

    public Screens(UiActions actions) {
        this.actions = actions;
        for (int i = 0; i < Game.MAX_PLAYERS; i++) {
            names[i] = new GuiString("Player " + (i + 1), Player.MAX_NAME_LENGTH);
            kinds[i] = new GuiInt(0);
            bots[i] = new GuiInt(0);
        }
    }

    public Screen screen() {
        return screen;
    }

    public void show(Screen s) {
        screen = s;
        formError = null;
    }

    /** Builds this frame's UI. */
    public void draw(UiView view) {
        float w = Gui.displayWidth(), h = Gui.displayHeight();
        switch (screen) {
            case MAIN_MENU -> mainMenu(view, w, h);
            case COURSES -> courses(view, w, h);
            case NEW_GAME -> newGame(view, w, h);
            case SETTINGS -> settingsScreen.settings(view, w, h);
            case PLAYING -> hud.hud(view, w, h, true);
            case PAUSED -> {
                hud.hud(view, w, h, false);
                pause(w, h);
            }
            case SCORECARD -> scorecard(view, w, h);
            case TEST_BOT -> hud.hud(view, w, h, false);
            case ROUND_CARD -> {
                // The final card says all the HUD would (and stands where it would): the course turns beside it.
                if (view.round() == null || !view.round().isOver()) hud.hud(view, w, h, false);
                roundCard(view, w, h);
            }
            case HELP -> help(w, h);
            case REPLAY -> {
                Gui.setNextWindowPos(w * 0.5f, 12, GuiCond.Always, 0.5f, 0f);
                Gui.begin("##replay", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
                Gui.alignTextToFramePadding();
                Gui.textColored(1f, 0.85f, 0.3f, 1f, view.replayCaption() == null ? "Replay" : view.replayCaption());
                Gui.sameLine();
                if (Gui.button("Stop")) actions.stopReplay();
                Gui.end();
            }
        }
        if (view.notice() != null) {
            Gui.setNextWindowPos(w * 0.5f, 16, GuiCond.Always, 0.5f, 0f);
            Gui.begin("Notice##notice", GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize
                    | GuiWindowFlags.NoMove);
            Gui.text(view.notice());
            if (Gui.button("Dismiss")) actions.dismissNotice();
            Gui.end();
        }
        if (view.message() != null) {
            Gui.setNextWindowPos(w * 0.5f, h - 16, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##message", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize
                    | GuiWindowFlags.NoInputs | GuiWindowFlags.NoFocusOnAppearing);
            Gui.text(view.message());
            Gui.end();
        }
    }

    static void centre(float w, float h) {
        Gui.setNextWindowPos(w * 0.5f, h * 0.5f, GuiCond.Always, 0.5f, 0.5f);
    }

    /** A final card stands at the left, so that the course the camera turns round shows beside it. */
    static void leftOfCourse(float w, float h) {
        Gui.setNextWindowPos(w * FINAL_CARD_LEFT, h * 0.5f, GuiCond.Always, 0f, 0.5f);
    }

    /** The final card's left edge, a share of the screen's width (the camera keeps the course right of it). */
    public static final float FINAL_CARD_LEFT = 0.03f;

    private void mainMenu(UiView view, float w, float h) {
        centre(w, h);
        Gui.begin("Minigolf", PANEL);
        Gui.text(view.chosenRound() != null ? "Round: " + view.chosenRound().name() + " (" + view.chosenRound().size()
                + " holes, par " + view.chosenRound().par() + ")" : "Course: " + view.world().course().name());
        Gui.separator();
        float bw = 300, bh = 0;
        if (Gui.button("Play", bw, bh)) show(Screen.NEW_GAME);
        if (Gui.button("Rounds and practice holes", bw, bh)) {
            actions.refreshCourses(); // a course saved by the editor a moment ago is listed
            show(Screen.COURSES);
        }
        List<String> botNames = BotCatalog.names();
        if (Gui.button("Test bot", bw, bh) && !botNames.isEmpty()) {
            actions.testBot(botNames.get(Math.min(testBot.get(), botNames.size() - 1)));
        }
        Gui.sameLine();
        Gui.setNextItemWidth(120);
        Gui.combo("##testbot", testBot, botNames.toArray(new String[0]));
        if (Gui.button("Create course", bw, bh)) actions.createCourse();
        if (!view.savedGames().isEmpty()) {
            Gui.setNextItemWidth(bw); // as wide as the buttons
            if (Gui.beginMenu("Load saved game")) {
                // Newest first, by round or course, players and date (the file names are only timestamps).
                List<Path> saves = new java.util.ArrayList<>(view.savedGames());
                java.util.Collections.reverse(saves);
                for (Path p : saves) {
                    if (Gui.menuItem(minigolf.game.SavedGameSummary.cached(p).label() + "##" + p)) actions.loadGame(p);
                }
                Gui.endMenu();
            }
        }
        if (Gui.button("Settings", bw, bh)) settingsScreen.openSettings(view, Screen.MAIN_MENU);
        if (Gui.button("Help (F1)", bw, bh)) openHelp();
        if (Gui.button("Quit", bw, bh)) actions.quit();
        Gui.end();
    }

    private void courses(UiView view, float w, float h) {
        centre(w, h);
        Gui.setNextWindowSize(Math.min(w - 40, 760), Math.min(h - 40, 560));
        Gui.begin("Select course", GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize);
        Gui.textColored(1f, 0.85f, 0.3f, 1f, "Rounds");
        for (UiView.RoundEntry r : view.rounds()) {
            String label = String.format(Locale.ROOT, "%s  (%d holes, par %d)##%s", r.round().name(), r.round().size(),
                    r.round().par(), r.file());
            if (Gui.button(label, 420, 0)) actions.chooseRound(r.round());
        }
        if (view.rounds().isEmpty()) Gui.text("(no rounds found)");
        Gui.separator();
        Gui.textColored(1f, 0.85f, 0.3f, 1f, "Practice (single holes)");
        // Three previews to a row, each course's name under its preview.
        List<UiView.CourseEntry> all = view.courses();
        for (int row = 0; row < all.size(); row += 3) {
            List<UiView.CourseEntry> three = all.subList(row, Math.min(all.size(), row + 3));
            float cell = 0;
            for (int i = 0; i < three.size(); i++) {
                UiView.CourseEntry c = three.get(i);
                if (i > 0) Gui.sameLine();
                int tex = view.thumbnail(c);
                if (tex != 0) {
                    if (Gui.imageButton(tex, 200, 120)) actions.selectCourse(c.file());
                } else if (Gui.button("rendering...##" + c.file(), 208, 128)) {
                    actions.selectCourse(c.file());
                }
                cell = Gui.getItemRectSizeX();
            }
            for (int i = 0; i < three.size(); i++) {
                UiView.CourseEntry c = three.get(i);
                if (i > 0) Gui.sameLine(i * (cell + Gui.itemSpacingX()));
                Gui.text(c.name() + (c.own() ? " (yours)" : ""));
            }
        }
        Gui.separator();
        if (Gui.button("Back")) show(Screen.MAIN_MENU);
        Gui.end();
    }

    private void newGame(UiView view, float w, float h) {
        centre(w, h);
        Gui.begin("New game: " + (view.chosenRound() != null ? view.chosenRound().name() : view.world().course().name())
                + "###newgame", PANEL);
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
                Gui.combo("##bot", bots[i], botNames.toArray(new String[0]));
            }
            Gui.popID();
        }
        Gui.text("Stroke limit: " + view.settings().strokeLimit() + " (pick up and score "
                + (view.settings().strokeLimit() + 1) + "; change it in Settings)");
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (Gui.button("Tee off")) {
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
                actions.startGame(players);
            } catch (IllegalArgumentException e) {
                formError = e.getMessage();
            }
        }
        Gui.sameLine();
        if (Gui.button("Back")) show(Screen.MAIN_MENU);
        Gui.end();
    }

    /** Opens a screen as its button does: the settings form filled from the view, help remembering where it was opened. */
    public void open(Screen s, UiView view) {
        if (s == Screen.SETTINGS) settingsScreen.openSettings(view, screen);
        else if (s == Screen.HELP) openHelp();
        else show(s);
    }

    /** Presses the Settings screen's "Apply" with the form as it stands (tests: the button's own code). */
    public void applySettingsForm(UiView view) {
        settingsScreen.apply(view);
    }

    private void pause(float w, float h) {
        centre(w, h);
        Gui.begin("Paused", PANEL);
        float bw = 240;
        if (Gui.button("Resume", bw, 0)) show(Screen.PLAYING);
        if (lastView != null) watchHoles(lastView.round());
        if (Gui.button("Save game", bw, 0)) actions.saveGame();
        if (Gui.button("Settings", bw, 0)) settingsFromPause();
        if (Gui.button("Main menu", bw, 0)) actions.toMainMenu();
        if (Gui.button("Quit", bw, 0)) actions.quit();
        Gui.end();
    }

    private UiView lastView;

    /** "Watch hole: 1 2 3 ...": any finished hole of the round again, as played (nothing for a single course). */
    private void watchHoles(minigolf.game.RoundGame round) {
        if (round == null || round.holesFinished() == 0) return;
        Gui.text("Watch hole:");
        for (int hole = 0; hole < round.holesFinished(); hole++) {
            if (round.holeStrokes(hole).isEmpty()) continue;
            if (hole % 9 != 0) Gui.sameLine();
            if (Gui.button((hole + 1) + "##watch", 24, 0)) actions.watchHole(hole);
        }
    }

    private void settingsFromPause() {
        if (lastView != null) settingsScreen.openSettings(lastView, Screen.PAUSED);
    }

    /** Remembers the view for actions that need it outside draw (the pause menu's settings). */
    public void remember(UiView view) {
        lastView = view;
    }

    private void scorecard(UiView view, float w, float h) {
        leftOfCourse(w, h);
        Gui.begin("Scorecard: " + view.world().course().name(), PANEL);
        Game g = view.game();
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
                Gui.text(l.status().jsonName());
            }
            Gui.endTable();
        }
        if (Gui.button("Watch again")) actions.watchReplay();
        Gui.sameLine();
        if (Gui.button("Play again")) show(Screen.NEW_GAME);
        Gui.sameLine();
        if (Gui.button("Main menu")) actions.toMainMenu();
        Gui.end();
    }

    private void roundCard(UiView view, float w, float h) {
        minigolf.game.RoundGame rg = view.round();
        if (rg == null) return;
        minigolf.game.RoundScorecard card = rg.scorecard();
        int holes = card.pars().length;
        if (card.over()) leftOfCourse(w, h);
        else centre(w, h);
        Gui.begin((card.over() ? "Final card: " : "Card: ") + card.roundName() + "###roundcard", PANEL);
        if (Gui.beginTable("##card", holes + 3, GuiTableFlags.Borders | GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) {
            Gui.tableSetupColumn("Hole");
            for (int i = 0; i < holes; i++) Gui.tableSetupColumn(String.valueOf(i + 1));
            Gui.tableSetupColumn("Total");
            Gui.tableSetupColumn("To par");
            Gui.tableHeadersRow();
            Gui.tableNextRow();
            Gui.tableSetColumnIndex(0);
            Gui.text("Par");
            for (int i = 0; i < holes; i++) {
                Gui.tableSetColumnIndex(i + 1);
                Gui.text(String.valueOf(card.pars()[i]));
            }
            Gui.tableSetColumnIndex(holes + 1);
            Gui.text(String.valueOf(card.totalPar()));
            for (int s = 0; s < card.rows().size(); s++) {
                minigolf.game.RoundScorecard.Row row = card.rows().get(s);
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                float[] c = PlayerColors.of(s);
                Gui.textColored(c[0], c[1], c[2], 1f, row.name());
                for (int i = 0; i < row.holes().length; i++) {
                    Gui.tableSetColumnIndex(i + 1);
                    int score = row.holes()[i], par = card.pars()[i];
                    if (score == 1) Gui.textColored(1f, 0.85f, 0.2f, 1f, "1");
                    else if (score < par) Gui.textColored(0.5f, 1f, 0.5f, 1f, String.valueOf(score));
                    else if (score > par) Gui.textColored(1f, 0.6f, 0.5f, 1f, String.valueOf(score));
                    else Gui.text(String.valueOf(score));
                }
                Gui.tableSetColumnIndex(holes + 1);
                Gui.text(String.valueOf(row.total()));
                Gui.tableSetColumnIndex(holes + 2);
                Gui.text(minigolf.game.RoundScorecard.formatToPar(card.toPar(s)));
            }
            Gui.endTable();
        }
        List<Integer> winners = card.winners();
        if (!winners.isEmpty()) {
            List<String> names = winners.stream().map(s -> card.rows().get(s).name()).toList();
            Gui.textColored(1f, 0.85f, 0.3f, 1f, (names.size() == 1 ? "Winner: " : "Tied for the win: ") + String.join(", ", names));
        }
        minigolf.game.HighScores scores = view.highScores();
        if (scores != null) {
            Gui.separator();
            for (int s = 0; s < card.rows().size(); s++) {
                String n = card.rows().get(s).name();
                Integer best = scores.personalBest(card.roundName(), n);
                int hole = Math.max(0, card.holesPlayed() - 1);
                Integer holeBest = card.holesPlayed() > 0 ? scores.personalBest(card.roundName(), hole, n) : null;
                Gui.text(n + ": best round " + (best == null ? "-" : best) + (holeBest == null ? ""
                        : ", best on hole " + (hole + 1) + ": " + holeBest));
            }
            if (card.over()) {
                Gui.separator();
                Gui.textColored(1f, 0.85f, 0.3f, 1f, "High scores: " + card.roundName());
                if (Gui.beginTable("##high", 4, GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) {
                    int place = 1;
                    for (minigolf.game.HighScores.Entry e : scores.table(card.roundName())) {
                        Gui.tableNextRow();
                        Gui.tableSetColumnIndex(0);
                        Gui.text("#" + place++);
                        Gui.tableSetColumnIndex(1);
                        Gui.text(e.name());
                        Gui.tableSetColumnIndex(2);
                        Gui.text(e.score() + " (" + minigolf.game.RoundScorecard.formatToPar(e.score() - card.totalPar()) + ")");
                        Gui.tableSetColumnIndex(3);
                        Gui.text(e.date().toString());
                    }
                    Gui.endTable();
                }
            }
        }
        if (Gui.button("Watch hole " + (card.holesPlayed()) + " again", 220, 0)) actions.watchReplay();
        if (card.holesPlayed() > 1) watchHoles(view.round());
        if (!card.over()) {
            if (Gui.button("Next hole", 160, 0)) actions.nextHole();
            Gui.sameLine();
            if (Gui.button("Save and quit", 160, 0)) {
                actions.saveGame();
                actions.toMainMenu();
            }
        } else {
            if (Gui.button("Play again", 160, 0)) show(Screen.NEW_GAME);
            Gui.sameLine();
            if (Gui.button("Main menu", 160, 0)) actions.toMainMenu();
        }
        Gui.end();
    }

    private Screen helpReturn = Screen.MAIN_MENU;

    /** Opens the help screen; ESC or "Back" returns to where it was opened. */
    public void openHelp() {
        if (screen != Screen.HELP) helpReturn = screen;
        show(Screen.HELP);
    }

    /** Where the help screen goes back to. */
    public void closeHelp() {
        show(helpReturn);
    }

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
            {"Pause / back", "ESC"},
            {"Full screen", "F11"},
            {"This help", "F1"},
    };

    private void help(float w, float h) {
        centre(w, h);
        Gui.begin("Help###help", PANEL);
        Gui.textColored(1f, 0.85f, 0.3f, 1f, "How to play");
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
        if (Gui.button("Back", 160, 0)) closeHelp();
        Gui.end();
    }
}
