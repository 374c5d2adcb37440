package minigolf.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTableFlags;
import imgui.flag.ImGuiWindowFlags;
import imgui.type.ImBoolean;
import imgui.type.ImDouble;
import imgui.type.ImInt;
import imgui.type.ImString;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.course.CourseException;
import minigolf.game.BallReadout;
import minigolf.game.BotCatalog;
import minigolf.game.BotTurn;
import minigolf.game.CourseEdits;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerKind;
import minigolf.game.PlayerState;
import minigolf.game.ScoreLine;
import minigolf.game.UserSettings;
import minigolf.physics.Integrator;

/** The ImGui screens: main menu, course choice, new game, settings, HUD, pause menu, scorecard. */
public final class Screens {
    private static final int PANEL = ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoResize
            | ImGuiWindowFlags.AlwaysAutoResize;
    private static final String[] KINDS = {"Human", "Bot"};
    private static final String[] INTEGRATORS = {"euler", "rk2", "rk4"};

    private final UiActions actions;
    private Screen screen = Screen.MAIN_MENU;
    private Screen settingsReturn = Screen.MAIN_MENU;

    // New-game form.
    private final ImInt playerCount = new ImInt(2);
    private final ImString[] names = new ImString[Game.MAX_PLAYERS];
    private final ImInt[] kinds = new ImInt[Game.MAX_PLAYERS];
    private final ImInt[] bots = new ImInt[Game.MAX_PLAYERS];
    // Typed shot.
    private final ImDouble typedVx = new ImDouble(1.0);
    private final ImDouble typedVy = new ImDouble(0.0);
    private final ImDouble typedVz = new ImDouble(0.0);
    // Settings form.
    private final ImInt integrator = new ImInt(2);
    private final ImInt stepsPerSecond = new ImInt(60);
    private final ImBoolean vsync = new ImBoolean(true);
    private final ImBoolean realistic = new ImBoolean(false);
    private final ImBoolean hideFriction = new ImBoolean(false);
    private final ImInt frameLimit = new ImInt(60);
    private final ImInt strokeLimit = new ImInt(Game.DEFAULT_STROKE_LIMIT);
    private final float[] mouseSpeed = {1f};
    private final ImBoolean aimGuide = new ImBoolean(true);
    private final ImBoolean antiAliasing = new ImBoolean(false);
    private final float[] masterVolume = {0.8f}, effectsVolume = {1f}, ambienceVolume = {0.35f};
    private final ImDouble[] course = new ImDouble[9];
    private final ImInt testBot = new ImInt(0);
    /** The HUD's physics readout (position, velocity, acceleration, slope, friction): off unless asked for. */
    private final ImBoolean details = new ImBoolean(false);
    private String formError;

    public Screens(UiActions actions) {
        this.actions = actions;
        for (int i = 0; i < Game.MAX_PLAYERS; i++) {
            names[i] = new ImString("Player " + (i + 1), Player.MAX_NAME_LENGTH);
            kinds[i] = new ImInt(0);
            bots[i] = new ImInt(0);
        }
        for (int i = 0; i < course.length; i++) course[i] = new ImDouble();
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
        float w = ImGui.getIO().getDisplaySizeX(), h = ImGui.getIO().getDisplaySizeY();
        switch (screen) {
            case MAIN_MENU -> mainMenu(view, w, h);
            case COURSES -> courses(view, w, h);
            case NEW_GAME -> newGame(view, w, h);
            case SETTINGS -> settings(view, w, h);
            case PLAYING -> hud(view, w, h, true);
            case PAUSED -> {
                hud(view, w, h, false);
                pause(w, h);
            }
            case SCORECARD -> scorecard(view, w, h);
            case TEST_BOT -> hud(view, w, h, false);
            case ROUND_CARD -> {
                hud(view, w, h, false);
                roundCard(view, w, h);
            }
            case HELP -> help(w, h);
            case REPLAY -> {
                ImGui.setNextWindowPos(w * 0.5f, 12, ImGuiCond.Always, 0.5f, 0f);
                ImGui.begin("##replay", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize);
                ImGui.textColored(1f, 0.85f, 0.3f, 1f, view.replayCaption() == null ? "Replay" : view.replayCaption());
                ImGui.sameLine();
                if (ImGui.button("Stop")) actions.stopReplay();
                ImGui.end();
            }
        }
        if (view.notice() != null) {
            ImGui.setNextWindowPos(w * 0.5f, 16, ImGuiCond.Always, 0.5f, 0f);
            ImGui.begin("Notice##notice", ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.AlwaysAutoResize
                    | ImGuiWindowFlags.NoMove);
            ImGui.text(view.notice());
            if (ImGui.button("Dismiss")) actions.dismissNotice();
            ImGui.end();
        }
        if (view.message() != null) {
            ImGui.setNextWindowPos(w * 0.5f, h - 16, ImGuiCond.Always, 0.5f, 1f);
            ImGui.begin("##message", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                    | ImGuiWindowFlags.NoInputs | ImGuiWindowFlags.NoFocusOnAppearing);
            ImGui.text(view.message());
            ImGui.end();
        }
    }

    private static void centre(float w, float h) {
        ImGui.setNextWindowPos(w * 0.5f, h * 0.5f, ImGuiCond.Always, 0.5f, 0.5f);
    }

    private void mainMenu(UiView view, float w, float h) {
        centre(w, h);
        ImGui.begin("Minigolf", PANEL);
        ImGui.text(view.chosenRound() != null ? "Round: " + view.chosenRound().name() + " (" + view.chosenRound().size()
                + " holes, par " + view.chosenRound().par() + ")" : "Course: " + view.world().course().name());
        ImGui.separator();
        float bw = 300, bh = 0;
        if (ImGui.button("Play", bw, bh)) show(Screen.NEW_GAME);
        if (ImGui.button("Rounds and practice holes", bw, bh)) {
            actions.refreshCourses(); // a course saved by the editor a moment ago is listed
            show(Screen.COURSES);
        }
        List<String> botNames = BotCatalog.names();
        if (ImGui.button("Test bot", bw, bh) && !botNames.isEmpty()) {
            actions.testBot(botNames.get(Math.min(testBot.get(), botNames.size() - 1)));
        }
        ImGui.sameLine();
        ImGui.setNextItemWidth(120);
        ImGui.combo("##testbot", testBot, botNames.toArray(new String[0]));
        if (ImGui.button("Create course", bw, bh)) actions.createCourse();
        if (!view.savedGames().isEmpty() && ImGui.beginMenu("Load saved game")) {
            // Newest first, by round or course, players and date (the file names are only timestamps).
            List<Path> saves = new java.util.ArrayList<>(view.savedGames());
            java.util.Collections.reverse(saves);
            for (Path p : saves) {
                if (ImGui.menuItem(minigolf.game.SavedGameSummary.cached(p).label() + "##" + p)) actions.loadGame(p);
            }
            ImGui.endMenu();
        }
        if (ImGui.button("Settings", bw, bh)) openSettings(view, Screen.MAIN_MENU);
        if (ImGui.button("Help (F1)", bw, bh)) openHelp();
        if (ImGui.button("Quit", bw, bh)) actions.quit();
        ImGui.end();
    }

    private void courses(UiView view, float w, float h) {
        centre(w, h);
        ImGui.setNextWindowSize(Math.min(w - 40, 760), Math.min(h - 40, 560));
        ImGui.begin("Select course", ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoResize);
        ImGui.textColored(1f, 0.85f, 0.3f, 1f, "Rounds");
        for (UiView.RoundEntry r : view.rounds()) {
            String label = String.format(Locale.ROOT, "%s  (%d holes, par %d)##%s", r.round().name(), r.round().size(),
                    r.round().par(), r.file());
            if (ImGui.button(label, 420, 0)) actions.chooseRound(r.round());
        }
        if (view.rounds().isEmpty()) ImGui.text("(no rounds found)");
        ImGui.separator();
        ImGui.textColored(1f, 0.85f, 0.3f, 1f, "Practice (single holes)");
        int column = 0;
        for (UiView.CourseEntry c : view.courses()) {
            ImGui.beginGroup();
            int tex = view.thumbnail(c);
            if (tex != 0) {
                if (ImGui.imageButton(tex, 200, 120, 0, 1, 1, 0)) actions.selectCourse(c.file());
            } else if (ImGui.button("rendering...##" + c.file(), 208, 128)) {
                actions.selectCourse(c.file());
            }
            ImGui.text(c.name() + (c.own() ? " (yours)" : ""));
            ImGui.endGroup();
            if (++column % 3 != 0) ImGui.sameLine();
        }
        ImGui.newLine();
        ImGui.separator();
        if (ImGui.button("Back")) show(Screen.MAIN_MENU);
        ImGui.end();
    }

    private void newGame(UiView view, float w, float h) {
        centre(w, h);
        ImGui.begin("New game: " + (view.chosenRound() != null ? view.chosenRound().name() : view.world().course().name())
                + "###newgame", PANEL);
        ImGui.sliderInt("Players", playerCount.getData(), 1, Game.MAX_PLAYERS);
        List<String> botNames = BotCatalog.names();
        for (int i = 0; i < playerCount.get(); i++) {
            ImGui.pushID(i);
            ImGui.setNextItemWidth(200);
            ImGui.inputText("##name", names[i]);
            ImGui.sameLine();
            ImGui.setNextItemWidth(100);
            ImGui.combo("##kind", kinds[i], KINDS);
            if (kinds[i].get() == 1) {
                ImGui.sameLine();
                ImGui.setNextItemWidth(120);
                ImGui.combo("##bot", bots[i], botNames.toArray(new String[0]));
            }
            ImGui.popID();
        }
        ImGui.text("Stroke limit: " + view.settings().strokeLimit() + " (pick up and score "
                + (view.settings().strokeLimit() + 1) + "; change it in Settings)");
        if (formError != null) ImGui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (ImGui.button("Tee off")) {
            try {
                List<Player> players = new ArrayList<>();
                for (int i = 0; i < playerCount.get(); i++) {
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
        ImGui.sameLine();
        if (ImGui.button("Back")) show(Screen.MAIN_MENU);
        ImGui.end();
    }

    private void openSettings(UiView view, Screen returnTo) {
        UserSettings s = view.settings();
        integrator.set(s.integrator().ordinal());
        stepsPerSecond.set((int) Math.round(1 / s.dt()));
        vsync.set(s.vsync());
        realistic.set(s.noisePosition() > 0 || s.noiseVelocity() > 0);
        hideFriction.set(s.hideFrictionFromBots());
        frameLimit.set(s.frameLimit());
        strokeLimit.set(s.strokeLimit());
        mouseSpeed[0] = (float) s.mouseSpeed();
        aimGuide.set(s.aimGuide());
        antiAliasing.set(s.antiAliasing());
        masterVolume[0] = (float) view.volumes().master();
        effectsVolume[0] = (float) view.volumes().effects();
        ambienceVolume[0] = (float) view.volumes().ambience();
        CourseEdits e = CourseEdits.of(view.world().course());
        double[] v = {e.gravity(), e.kineticFriction(), e.staticFriction(), e.maxSpeed(), e.startX(), e.startY(),
                e.holeX(), e.holeY(), e.holeRadius()};
        for (int i = 0; i < v.length; i++) course[i].set(v[i]);
        settingsReturn = returnTo;
        show(Screen.SETTINGS);
    }

    private void settings(UiView view, float w, float h) {
        centre(w, h);
        ImGui.begin("Settings", PANEL);
        ImGui.text("Yours (kept in your config folder)");
        ImGui.combo("Integrator", integrator, INTEGRATORS);
        ImGui.inputInt("Physics steps per second", stepsPerSecond);
        ImGui.checkbox("Vsync", vsync);
        ImGui.inputInt("Frame limit (0 = none)", frameLimit);
        ImGui.inputInt("Stroke limit", strokeLimit);
        ImGui.sliderFloat("Mouse speed", mouseSpeed, 0.2f, 5f);
        ImGui.checkbox("Realistic (every stroke strays a little, bots' too; next game)", realistic);
        ImGui.checkbox("Hide friction from bots (they learn it from their strokes)", hideFriction);
        ImGui.checkbox("Aim guide (off: pro)", aimGuide);
        if (ImGui.isItemHovered()) ImGui.setTooltip("While aiming, dots show where the ball goes in its first second");
        ImGui.checkbox("Smooth edges (FXAA)", antiAliasing);
        if (ImGui.isItemHovered()) ImGui.setTooltip("Anti-aliasing where there is no MSAA; costs about 8 ms a frame with software rendering");
        ImGui.sliderFloat("Volume", masterVolume, 0f, 1f);
        ImGui.sliderFloat("Effects", effectsVolume, 0f, 1f);
        ImGui.sliderFloat("Ambience", ambienceVolume, 0f, 1f);
        ImGui.separator();
        ImGui.text("This course (" + view.world().course().name() + "): applies to the next game");
        String[] labels = {"Gravity (m/s^2)", "Kinetic friction", "Static friction", "Max speed (m/s)", "Start x",
                "Start y", "Hole x", "Hole y", "Hole radius"};
        for (int i = 0; i < labels.length; i++) ImGui.inputDouble(labels[i], course[i], 0, 0, "%.4f");
        if (formError != null) ImGui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (ImGui.button("Apply")) {
            try {
                int sps = stepsPerSecond.get();
                UserSettings s = view.settings().withIntegrator(Integrator.values()[integrator.get()])
                        .withDt(sps > 0 ? 1.0 / sps : 0).withVsync(vsync.get()).withFrameLimit(frameLimit.get())
                        .withStrokeLimit(strokeLimit.get()).withMouseSpeed(mouseSpeed[0])
                        .withHideFrictionFromBots(hideFriction.get())
                        .withAimGuide(aimGuide.get()).withAntiAliasing(antiAliasing.get());
                // Keeps noise levels set in the settings file; the box turns the default levels on or all noise off.
                boolean wasOn = s.noisePosition() > 0 || s.noiseVelocity() > 0;
                if (realistic.get() != wasOn) {
                    s = realistic.get() ? s.withNoise(UserSettings.REALISTIC_POSITION, UserSettings.REALISTIC_VELOCITY)
                            : s.withNoise(0, 0);
                }
                CourseEdits e = new CourseEdits(course[0].get(), course[1].get(), course[2].get(), course[3].get(),
                        course[4].get(), course[5].get(), course[6].get(), course[7].get(), course[8].get());
                actions.applySettings(s, e);
                actions.applyVolumes(new minigolf.game.AudioSettings(masterVolume[0], effectsVolume[0], ambienceVolume[0]));
                formError = null;
                show(settingsReturn);
            } catch (IllegalArgumentException e) {
                formError = e.getMessage();
            } catch (RuntimeException e) {
                formError = e.getCause() instanceof CourseException ce ? ce.detail() : e.getMessage();
            }
        }
        ImGui.sameLine();
        if (ImGui.button("Cancel")) show(settingsReturn);
        ImGui.end();
    }

    private void hud(UiView view, float w, float h, boolean interactive) {
        Game g = view.game();
        ImGui.setNextWindowPos(12, 12, ImGuiCond.Always);
        ImGui.begin("##hud", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove);
        minigolf.game.RoundGame rg = view.round();
        if (rg != null) {
            ImGui.textColored(0.6f, 0.9f, 1f, 1f, String.format(Locale.ROOT, "%s  -  hole %d of %d  -  par %d",
                    rg.round().name(), rg.holeIndex() + 1, rg.round().size(), rg.hole().par()));
        }
        if (g != null) {
            int cur = g.currentPlayer();
            if (cur >= 0) {
                Player p = g.players().get(cur);
                ImGui.textColored(1f, 0.85f, 0.3f, 1f, p.name() + (p.isBot() ? " (bot: " + p.bot() + ")" : "") + " to play");
            }
            for (int i = 0; i < g.players().size(); i++) {
                PlayerState s = g.player(i);
                float[] c = PlayerColors.of(i);
                ImGui.textColored(c[0], c[1], c[2], 1f, String.format(Locale.ROOT, "%-12s", g.players().get(i).name()));
                ImGui.sameLine();
                ImGui.text(String.format(Locale.ROOT, "strokes %d%s%s%s", s.total(),
                        view.round() != null ? " (par " + view.round().hole().par() + ")" : "",
                        s.penalties() > 0 ? " (" + s.penalties() + " penalty)" : "",
                        s.status() == minigolf.game.PlayerStatus.PLAYING ? "" : ", " + s.status().jsonName()));
            }
        }
        double aim = view.aimSpeed();
        if (aim >= 0 && g != null) {
            double max = view.world().physics().maxSpeed();
            ImGui.progressBar((float) (aim / max), 260, 0, String.format(Locale.ROOT, "power %.0f%%", 100 * aim / max));
        }
        if (g != null && !g.isOver()) ImGui.text(minigolf.game.Loft.describe(view.loftDegrees()) + "   (wheel while aiming, Up/Down)");
        if (g != null) ImGui.checkbox("details", details);
        BallReadout r = details.get() ? view.readout() : null;
        if (r != null) {
            ImGui.separator();
            ImGui.text(String.format(Locale.ROOT, "position  (%.3f, %.3f, %.3f) m", r.x(), r.y(), r.z()));
            ImGui.text(String.format(Locale.ROOT, "velocity  (%.3f, %.3f) m/s  |v| %.3f", r.vx(), r.vy(), r.speed()));
            ImGui.text(String.format(Locale.ROOT, "accel.    (%.3f, %.3f) m/s^2  |a| %.3f", r.ax(), r.ay(), r.acceleration()));
            ImGui.text(String.format(Locale.ROOT, "slope     %.3f (%.1f deg)", r.slope(), r.slopeDegrees()));
            ImGui.text(String.format(Locale.ROOT, "friction  mu_k %.3f  mu_s %.3f", r.kineticFriction(), r.staticFriction()));
        }
        ImGui.end();

        BotTurn bot = view.botTurn();
        if (bot != null) {
            PlanOverlay.draw(ImGui.getBackgroundDrawList(), bot.plan(), p -> view.toScreen(p[0], p[1]));
            ImGui.setNextWindowPos(w * 0.5f, h - 60, ImGuiCond.Always, 0.5f, 1f);
            ImGui.begin("##bot", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize);
            ImGui.text("Bot thinking: " + bot.message());
            ImGui.progressBar((float) bot.progress(), 320, 0);
            ImGui.sameLine();
            if (ImGui.button("Cancel")) actions.cancelBot();
            ImGui.end();
        }
        boolean humanToPlay = g != null && !g.isShotInFlight() && g.currentPlayer() >= 0
                && !g.players().get(g.currentPlayer()).isBot() && bot == null;
        if (interactive && humanToPlay) shotPanel(view, w, h);
    }

    private void shotPanel(UiView view, float w, float h) {
        double max = view.world().physics().maxSpeed();
        ImGui.setNextWindowPos(w - 12, h - 12, ImGuiCond.Always, 1f, 1f);
        ImGui.begin("Shot", ImGuiWindowFlags.NoCollapse | ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove);
        ImGui.text("Drag back from the ball to aim, release to hit,");
        ImGui.text("or type the velocity (max " + max + " m/s):");
        ImGui.setNextItemWidth(120);
        ImGui.inputDouble("vx", typedVx, 0.1, 0.5, "%.3f");
        ImGui.setNextItemWidth(120);
        ImGui.inputDouble("vy", typedVy, 0.1, 0.5, "%.3f");
        ImGui.setNextItemWidth(120);
        ImGui.inputDouble("vz (0 = putt)", typedVz, 0.1, 0.5, "%.3f");
        double speed = Math.sqrt(typedVx.get() * typedVx.get() + typedVy.get() * typedVy.get() + typedVz.get() * typedVz.get());
        ImGui.progressBar((float) Math.min(1, speed / max), 240, 0, String.format(Locale.ROOT, "%.2f m/s", speed));
        String problem = minigolf.game.AimModel.checkTyped(typedVx.get(), typedVy.get(), typedVz.get(), max);
        if (problem != null) ImGui.textColored(1f, 0.5f, 0.4f, 1f, problem);
        if (problem != null) ImGui.beginDisabled();
        if (ImGui.button("HIT", 120, 0)) actions.hit(typedVx.get(), typedVy.get(), typedVz.get());
        if (problem != null) ImGui.endDisabled();
        double aim = view.aimSpeed();
        if (aim >= 0) {
            ImGui.progressBar((float) (aim / max), 240, 0, String.format(Locale.ROOT, "power %.2f m/s", aim));
        }
        ImGui.end();
    }

    private void pause(float w, float h) {
        centre(w, h);
        ImGui.begin("Paused", PANEL);
        float bw = 240;
        if (ImGui.button("Resume", bw, 0)) show(Screen.PLAYING);
        if (ImGui.button("Save game", bw, 0)) actions.saveGame();
        if (ImGui.button("Settings", bw, 0)) settingsFromPause();
        if (ImGui.button("Main menu", bw, 0)) actions.toMainMenu();
        if (ImGui.button("Quit", bw, 0)) actions.quit();
        ImGui.end();
    }

    private UiView lastView;

    private void settingsFromPause() {
        if (lastView != null) openSettings(lastView, Screen.PAUSED);
    }

    /** Remembers the view for actions that need it outside draw (the pause menu's settings). */
    public void remember(UiView view) {
        lastView = view;
    }

    private void scorecard(UiView view, float w, float h) {
        centre(w, h);
        ImGui.begin("Scorecard: " + view.world().course().name(), PANEL);
        Game g = view.game();
        if (g != null && ImGui.beginTable("score", 6, ImGuiTableFlags.Borders | ImGuiTableFlags.RowBg)) {
            for (String c : new String[]{"Rank", "Player", "Strokes", "Penalties", "Score", ""}) ImGui.tableSetupColumn(c);
            ImGui.tableHeadersRow();
            for (ScoreLine l : g.scorecard().ranked()) {
                ImGui.tableNextRow();
                ImGui.tableSetColumnIndex(0);
                ImGui.text(String.valueOf(l.rank()));
                ImGui.tableSetColumnIndex(1);
                ImGui.text(l.name());
                ImGui.tableSetColumnIndex(2);
                ImGui.text(String.valueOf(l.strokes()));
                ImGui.tableSetColumnIndex(3);
                ImGui.text(String.valueOf(l.penalties()));
                ImGui.tableSetColumnIndex(4);
                ImGui.text(String.valueOf(l.score()));
                ImGui.tableSetColumnIndex(5);
                ImGui.text(l.status().jsonName());
            }
            ImGui.endTable();
        }
        if (ImGui.button("Watch again")) actions.watchReplay();
        ImGui.sameLine();
        if (ImGui.button("Play again")) show(Screen.NEW_GAME);
        ImGui.sameLine();
        if (ImGui.button("Main menu")) actions.toMainMenu();
        ImGui.end();
    }

    private void roundCard(UiView view, float w, float h) {
        minigolf.game.RoundGame rg = view.round();
        if (rg == null) return;
        minigolf.game.RoundScorecard card = rg.scorecard();
        int holes = card.pars().length;
        centre(w, h);
        ImGui.begin((card.over() ? "Final card: " : "Card: ") + card.roundName() + "###roundcard", PANEL);
        if (ImGui.beginTable("##card", holes + 3, ImGuiTableFlags.Borders | ImGuiTableFlags.RowBg | ImGuiTableFlags.SizingFixedFit)) {
            ImGui.tableSetupColumn("Hole");
            for (int i = 0; i < holes; i++) ImGui.tableSetupColumn(String.valueOf(i + 1));
            ImGui.tableSetupColumn("Total");
            ImGui.tableSetupColumn("To par");
            ImGui.tableHeadersRow();
            ImGui.tableNextRow();
            ImGui.tableSetColumnIndex(0);
            ImGui.text("Par");
            for (int i = 0; i < holes; i++) {
                ImGui.tableSetColumnIndex(i + 1);
                ImGui.text(String.valueOf(card.pars()[i]));
            }
            ImGui.tableSetColumnIndex(holes + 1);
            ImGui.text(String.valueOf(card.totalPar()));
            for (int s = 0; s < card.rows().size(); s++) {
                minigolf.game.RoundScorecard.Row row = card.rows().get(s);
                ImGui.tableNextRow();
                ImGui.tableSetColumnIndex(0);
                float[] c = PlayerColors.of(s);
                ImGui.textColored(c[0], c[1], c[2], 1f, row.name());
                for (int i = 0; i < row.holes().length; i++) {
                    ImGui.tableSetColumnIndex(i + 1);
                    int score = row.holes()[i], par = card.pars()[i];
                    if (score == 1) ImGui.textColored(1f, 0.85f, 0.2f, 1f, "1");
                    else if (score < par) ImGui.textColored(0.5f, 1f, 0.5f, 1f, String.valueOf(score));
                    else if (score > par) ImGui.textColored(1f, 0.6f, 0.5f, 1f, String.valueOf(score));
                    else ImGui.text(String.valueOf(score));
                }
                ImGui.tableSetColumnIndex(holes + 1);
                ImGui.text(String.valueOf(row.total()));
                ImGui.tableSetColumnIndex(holes + 2);
                ImGui.text(minigolf.game.RoundScorecard.formatToPar(card.toPar(s)));
            }
            ImGui.endTable();
        }
        List<Integer> winners = card.winners();
        if (!winners.isEmpty()) {
            List<String> names = winners.stream().map(s -> card.rows().get(s).name()).toList();
            ImGui.textColored(1f, 0.85f, 0.3f, 1f, (names.size() == 1 ? "Winner: " : "Tied for the win: ") + String.join(", ", names));
        }
        minigolf.game.HighScores scores = view.highScores();
        if (scores != null) {
            ImGui.separator();
            for (int s = 0; s < card.rows().size(); s++) {
                String n = card.rows().get(s).name();
                Integer best = scores.personalBest(card.roundName(), n);
                int hole = Math.max(0, card.holesPlayed() - 1);
                Integer holeBest = card.holesPlayed() > 0 ? scores.personalBest(card.roundName(), hole, n) : null;
                ImGui.text(n + ": best round " + (best == null ? "-" : best) + (holeBest == null ? ""
                        : ", best on hole " + (hole + 1) + ": " + holeBest));
            }
            if (card.over()) {
                ImGui.separator();
                ImGui.textColored(1f, 0.85f, 0.3f, 1f, "High scores: " + card.roundName());
                if (ImGui.beginTable("##high", 4, ImGuiTableFlags.RowBg | ImGuiTableFlags.SizingFixedFit)) {
                    int place = 1;
                    for (minigolf.game.HighScores.Entry e : scores.table(card.roundName())) {
                        ImGui.tableNextRow();
                        ImGui.tableSetColumnIndex(0);
                        ImGui.text("#" + place++);
                        ImGui.tableSetColumnIndex(1);
                        ImGui.text(e.name());
                        ImGui.tableSetColumnIndex(2);
                        ImGui.text(e.score() + " (" + minigolf.game.RoundScorecard.formatToPar(e.score() - card.totalPar()) + ")");
                        ImGui.tableSetColumnIndex(3);
                        ImGui.text(e.date().toString());
                    }
                    ImGui.endTable();
                }
            }
        }
        if (ImGui.button("Watch hole " + (card.holesPlayed()) + " again", 220, 0)) actions.watchReplay();
        if (!card.over()) {
            if (ImGui.button("Next hole", 160, 0)) actions.nextHole();
            ImGui.sameLine();
            if (ImGui.button("Save and quit", 160, 0)) {
                actions.saveGame();
                actions.toMainMenu();
            }
        } else {
            if (ImGui.button("Play again", 160, 0)) show(Screen.NEW_GAME);
            ImGui.sameLine();
            if (ImGui.button("Main menu", 160, 0)) actions.toMainMenu();
        }
        ImGui.end();
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
        ImGui.begin("Help###help", PANEL);
        ImGui.textColored(1f, 0.85f, 0.3f, 1f, "How to play");
        ImGui.text("Get the ball in the cup in as few strokes as you can. Par is what a good player needs.");
        ImGui.text("Water or out of bounds: one penalty stroke, the ball goes back to where the stroke began.");
        ImGui.text("A ball that rolls slowly enough over the cup drops in.");
        ImGui.separator();
        if (ImGui.beginTable("##controls", 2, ImGuiTableFlags.RowBg | ImGuiTableFlags.SizingFixedFit)) {
            for (String[] c : CONTROLS) {
                ImGui.tableNextRow();
                ImGui.tableSetColumnIndex(0);
                ImGui.textColored(0.6f, 0.9f, 1f, 1f, c[0]);
                ImGui.tableSetColumnIndex(1);
                ImGui.text(c[1]);
            }
            ImGui.endTable();
        }
        if (ImGui.button("Back", 160, 0)) closeHelp();
        ImGui.end();
    }
}
