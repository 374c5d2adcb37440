package minigolf.ui;

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

/** The screens (on {@link Gui}): main menu, course choice, new game, settings, HUD, pause menu, scorecard. */
public final class Screens {
    private static final int PANEL = GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize
            | GuiWindowFlags.AlwaysAutoResize;
    private static final String[] KINDS = {"Human", "Bot"};
    private static final String[] INTEGRATORS = {"euler", "rk2", "rk4"};

    private final UiActions actions;
    private Screen screen = Screen.MAIN_MENU;
    private Screen settingsReturn = Screen.MAIN_MENU;

    // New-game form.
    private final int[] playerCount = {2};
    private final GuiString[] names = new GuiString[Game.MAX_PLAYERS];
    private final GuiInt[] kinds = new GuiInt[Game.MAX_PLAYERS];
    private final GuiInt[] bots = new GuiInt[Game.MAX_PLAYERS];
    // Typed shot.
    private final GuiDouble typedVx = new GuiDouble(1.0);
    private final GuiDouble typedVy = new GuiDouble(0.0);
    private final GuiDouble typedVz = new GuiDouble(0.0);
    // Settings form.
    private final GuiInt integrator = new GuiInt(2);
    private final GuiInt stepsPerSecond = new GuiInt(60);
    private final GuiBool vsync = new GuiBool(true);
    private final GuiBool realistic = new GuiBool(false);
    private final GuiBool hideFriction = new GuiBool(false);
    private final GuiInt frameLimit = new GuiInt(60);
    private final GuiInt strokeLimit = new GuiInt(Game.DEFAULT_STROKE_LIMIT);
    private final float[] mouseSpeed = {1f};
    private final GuiBool aimGuide = new GuiBool(true);
    private final GuiBool antiAliasing = new GuiBool(false);
    private final float[] masterVolume = {0.8f}, effectsVolume = {1f}, ambienceVolume = {0.35f};
    private final GuiDouble[] course = new GuiDouble[9];
    private final GuiInt testBot = new GuiInt(0);
    /** The HUD's physics readout (position, velocity, acceleration, slope, friction): off unless asked for. */
    private final GuiBool details = new GuiBool(false);
    private String formError;

    public Screens(UiActions actions) {
        this.actions = actions;
        for (int i = 0; i < Game.MAX_PLAYERS; i++) {
            names[i] = new GuiString("Player " + (i + 1), Player.MAX_NAME_LENGTH);
            kinds[i] = new GuiInt(0);
            bots[i] = new GuiInt(0);
        }
        for (int i = 0; i < course.length; i++) course[i] = new GuiDouble();
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

    private static void centre(float w, float h) {
        Gui.setNextWindowPos(w * 0.5f, h * 0.5f, GuiCond.Always, 0.5f, 0.5f);
    }

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
        if (Gui.button("Settings", bw, bh)) openSettings(view, Screen.MAIN_MENU);
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
        if (s == Screen.SETTINGS) openSettings(view, screen);
        else if (s == Screen.HELP) openHelp();
        else show(s);
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
        Gui.begin("Settings", PANEL);
        Gui.text("Yours (kept in your config folder)");
        Gui.combo("Integrator", integrator, INTEGRATORS);
        Gui.inputInt("Physics steps per second", stepsPerSecond);
        Gui.inputInt("Frame limit (0 = none)", frameLimit);
        Gui.sameLine(); // pairs on a row: the form fits a 720-pixel-high window
        Gui.checkbox("Vsync", vsync);
        Gui.inputInt("Stroke limit", strokeLimit);
        Gui.sliderFloat("Mouse speed", mouseSpeed, 0.2f, 5f);
        Gui.checkbox("Realistic (every stroke strays a little, bots' too; next game)", realistic);
        Gui.checkbox("Hide friction from bots (they learn it from their strokes)", hideFriction);
        Gui.checkbox("Aim guide (off: pro)", aimGuide);
        if (Gui.isItemHovered()) Gui.setTooltip("While aiming, dots show where the ball goes in its first second");
        Gui.sameLine();
        Gui.checkbox("Smooth edges (FXAA)", antiAliasing);
        if (Gui.isItemHovered()) Gui.setTooltip("Anti-aliasing where there is no MSAA; costs about 8 ms a frame with software rendering");
        Gui.sliderFloat("Volume", masterVolume, 0f, 1f);
        Gui.sliderFloat("Effects", effectsVolume, 0f, 1f);
        Gui.sliderFloat("Ambience", ambienceVolume, 0f, 1f);
        Gui.separator();
        Gui.text("This course (" + view.world().course().name() + "): applies to the next game");
        String[] labels = {"Gravity (m/s^2)", "Kinetic friction", "Static friction", "Max speed (m/s)", "Start x",
                "Start y", "Hole x", "Hole y", "Hole radius"};
        for (int i = 0; i < labels.length; i++) {
            boolean pair = i >= 4 && i <= 7; // start x and y, hole x and y side by side
            if (pair) Gui.setNextItemWidth(100);
            if (pair && i % 2 == 1) Gui.sameLine();
            Gui.inputDouble(labels[i], course[i], 0, 0, "%.4f");
        }
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (Gui.button("Apply")) {
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
        Gui.sameLine();
        if (Gui.button("Cancel")) show(settingsReturn);
        Gui.end();
    }

    private void hud(UiView view, float w, float h, boolean interactive) {
        Game g = view.game();
        Gui.setNextWindowPos(12, 12, GuiCond.Always);
        Gui.begin("##hud", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        minigolf.game.RoundGame rg = view.round();
        if (rg != null) {
            Gui.textColored(0.6f, 0.9f, 1f, 1f, String.format(Locale.ROOT, "%s  -  hole %d of %d  -  par %d",
                    rg.round().name(), rg.holeIndex() + 1, rg.round().size(), rg.hole().par()));
        }
        if (g != null) {
            int cur = g.currentPlayer();
            if (cur >= 0) {
                Player p = g.players().get(cur);
                Gui.textColored(1f, 0.85f, 0.3f, 1f, p.name() + (p.isBot() ? " (bot: " + p.bot() + ")" : "") + " to play");
            }
            Gui.beginTable("##players", 2, GuiTableFlags.SizingFixedFit); // names of any width line up
            for (int i = 0; i < g.players().size(); i++) {
                PlayerState s = g.player(i);
                float[] c = PlayerColors.of(i);
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.textColored(c[0], c[1], c[2], 1f, g.players().get(i).name());
                Gui.tableSetColumnIndex(1);
                Gui.text(String.format(Locale.ROOT, "strokes %d%s%s%s", s.total(),
                        view.round() != null ? " (par " + view.round().hole().par() + ")" : "",
                        s.penalties() > 0 ? " (" + s.penalties() + " penalty)" : "",
                        s.status() == minigolf.game.PlayerStatus.PLAYING ? "" : ", " + s.status().jsonName()));
            }
            Gui.endTable();
        }
        double aim = view.aimSpeed();
        if (aim >= 0 && g != null) {
            double max = view.world().physics().maxSpeed();
            Gui.progressBar((float) (aim / max), 260, 0, String.format(Locale.ROOT, "power %.0f%%", 100 * aim / max));
        }
        if (g != null && !g.isOver()) Gui.text(minigolf.game.Loft.describe(view.loftDegrees()) + "   (wheel while aiming, Up/Down)");
        if (g != null) Gui.checkbox("details", details);
        BallReadout r = details.get() ? view.readout() : null;
        if (r != null) {
            Gui.separator();
            Gui.text(String.format(Locale.ROOT, "position  (%.3f, %.3f, %.3f) m", r.x(), r.y(), r.z()));
            Gui.text(String.format(Locale.ROOT, "velocity  (%.3f, %.3f) m/s  |v| %.3f", r.vx(), r.vy(), r.speed()));
            Gui.text(String.format(Locale.ROOT, "accel.    (%.3f, %.3f) m/s^2  |a| %.3f", r.ax(), r.ay(), r.acceleration()));
            Gui.text(String.format(Locale.ROOT, "slope     %.3f (%.1f deg)", r.slope(), r.slopeDegrees()));
            Gui.text(String.format(Locale.ROOT, "friction  mu_k %.3f  mu_s %.3f", r.kineticFriction(), r.staticFriction()));
        }
        Gui.end();

        BotTurn bot = view.botTurn();
        if (bot != null) {
            PlanOverlay.draw(Gui.getBackgroundDrawList(), bot.plan(), p -> view.toScreen(p[0], p[1]));
            Gui.setNextWindowPos(w * 0.5f, h - 60, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##bot", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
            Gui.text("Bot thinking: " + bot.message());
            Gui.progressBar((float) bot.progress(), 320, 0);
            Gui.sameLine();
            if (Gui.button("Cancel")) actions.cancelBot();
            Gui.end();
        }
        boolean humanToPlay = g != null && !g.isShotInFlight() && g.currentPlayer() >= 0
                && !g.players().get(g.currentPlayer()).isBot() && bot == null;
        if (interactive && humanToPlay) shotPanel(view, w, h);
    }

    private void shotPanel(UiView view, float w, float h) {
        double max = view.world().physics().maxSpeed();
        Gui.setNextWindowPos(w - 12, h - 12, GuiCond.Always, 1f, 1f);
        Gui.begin("Shot", GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        Gui.text("Drag back from the ball to aim, release to hit,");
        Gui.text("or type the velocity (max " + max + " m/s):");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vx", typedVx, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vy", typedVy, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vz (0 = putt)", typedVz, 0.1, 0.5, "%.3f");
        double speed = Math.sqrt(typedVx.get() * typedVx.get() + typedVy.get() * typedVy.get() + typedVz.get() * typedVz.get());
        Gui.progressBar((float) Math.min(1, speed / max), 240, 0, String.format(Locale.ROOT, "%.2f m/s", speed));
        String problem = minigolf.game.AimModel.checkTyped(typedVx.get(), typedVy.get(), typedVz.get(), max);
        if (problem != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, problem);
        if (problem != null) Gui.beginDisabled();
        if (Gui.button("HIT", 120, 0)) actions.hit(typedVx.get(), typedVy.get(), typedVz.get());
        if (problem != null) Gui.endDisabled();
        double aim = view.aimSpeed();
        if (aim >= 0) {
            Gui.progressBar((float) (aim / max), 240, 0, String.format(Locale.ROOT, "power %.2f m/s", aim));
        }
        Gui.end();
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
        if (lastView != null) openSettings(lastView, Screen.PAUSED);
    }

    /** Remembers the view for actions that need it outside draw (the pause menu's settings). */
    public void remember(UiView view) {
        lastView = view;
    }

    private void scorecard(UiView view, float w, float h) {
        centre(w, h);
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
        centre(w, h);
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
