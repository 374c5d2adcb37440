package minigolf.app;

import java.util.List;
import minigolf.game.HighScores;
import minigolf.game.RoundGame;
import minigolf.game.RoundScorecard;
import minigolf.ui.Gui;
import minigolf.ui.GuiTableFlags;
import minigolf.ui.Panels;
import minigolf.ui.PlayerColors;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * A round's card: between holes (every hole's par and scores, totals, to par, personal bests, "Next
 * hole", "Save and quit") and after the last (the winner and the round's high scores, at the left
 * while the camera turns round the whole last course). A scripted run moves on by itself.
 */
final class RoundCardScreen extends GameScreen {
    /** Frames a scripted run (--frames) shows the card between holes before it plays the next. */
    static final int SCRIPTED_FRAMES = 30;
    private int frames;
    /** Where the final card's "Play again" was drawn last ({x, y, width, height}), or null: a window test clicks it. */
    private float[] playAgain;

    RoundCardScreen(GameApp app) {
        super(app);
    }

    @Override
    public void show() {
        frames = 0;
        playAgain = null;
    }

    float[] playAgainBounds() {
        return playAgain;
    }

    private boolean over() {
        RoundGame rg = app.play().round();
        return rg != null && rg.isOver();
    }

    @Override
    public void update(double elapsed) {
        if (app.play().round() != null && !over() && app.scripted() && ++frames >= SCRIPTED_FRAMES) nextHole();
    }

    private void nextHole() {
        if (app.play().nextHole()) {
            app.scene().resetCamera();
            app.setScreen(app.screens().playing());
        } else {
            frames = 0; // the final card (this screen, now over)
        }
    }

    @Override
    public void render(float w, float h) {
        RoundGame rg = app.play().round();
        if (rg == null) return;
        // The final card says all the HUD would (and stands where it would): the course turns beside it.
        if (!rg.isOver()) app.hud().render(w, h, -1, 0);
        RoundScorecard card = rg.scorecard();
        int holes = card.pars().length;
        if (card.over()) Panels.leftOfCourse(w, h);
        else Panels.centre(w, h);
        Gui.begin((card.over() ? "Final card: " : "Card: ") + card.roundName() + "###roundcard", Panels.PANEL);
        table(card, holes);
        List<Integer> winners = card.winners();
        if (!winners.isEmpty()) {
            List<String> names = winners.stream().map(s -> card.rows().get(s).name()).toList();
            Panels.heading((names.size() == 1 ? "Winner: " : "Tied for the win: ") + String.join(", ", names));
        }
        HighScores scores = app.files().highScores();
        if (scores != null) bests(card, scores);
        if (Gui.button("Watch hole " + card.holesPlayed() + " again", 220, 0)) app.watchReplay();
        if (card.holesPlayed() > 1) PauseScreen.watchHoles(app, rg);
        if (!card.over()) {
            if (Gui.button("Next hole", 160, 0)) nextHole();
            Gui.sameLine();
            if (Gui.button("Save and quit", 160, 0)) {
                app.saveGame();
                app.toMainMenu();
            }
        } else {
            // After an online round, another room on the server rather than a hot-seat game.
            boolean again = Gui.button("Play again", 160, 0);
            playAgain = Gui.lastItemBounds();
            if (again) app.setScreen(app.play().online() != null ? app.screens().online() : app.screens().newGame());
            Gui.sameLine();
            if (Gui.button("Main menu", 160, 0)) app.toMainMenu();
        }
        Gui.end();
    }

    private static void table(RoundScorecard card, int holes) {
        if (!Gui.beginTable("##card", holes + 3, GuiTableFlags.Borders | GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) return;
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
            RoundScorecard.Row row = card.rows().get(s);
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
            Gui.text(RoundScorecard.formatToPar(card.toPar(s)));
        }
        Gui.endTable();
    }

    /** Each player's best round and best on the hole just played; after the last hole the round's high-score table. */
    private static void bests(RoundScorecard card, HighScores scores) {
        Gui.separator();
        for (int s = 0; s < card.rows().size(); s++) {
            String n = card.rows().get(s).name();
            Integer best = scores.personalBest(card.roundName(), n);
            int hole = Math.max(0, card.holesPlayed() - 1);
            Integer holeBest = card.holesPlayed() > 0 ? scores.personalBest(card.roundName(), hole, n) : null;
            Gui.text(n + ": best round " + (best == null ? "-" : best) + (holeBest == null ? ""
                    : ", best on hole " + (hole + 1) + ": " + holeBest));
        }
        if (!card.over()) return;
        Gui.separator();
        Panels.heading("High scores: " + card.roundName());
        if (Gui.beginTable("##high", 4, GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) {
            int place = 1;
            for (HighScores.Entry e : scores.table(card.roundName())) {
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.text("#" + place++);
                Gui.tableSetColumnIndex(1);
                Gui.text(e.name());
                Gui.tableSetColumnIndex(2);
                Gui.text(e.score() + " (" + RoundScorecard.formatToPar(e.score() - card.totalPar()) + ")");
                Gui.tableSetColumnIndex(3);
                Gui.text(e.date().toString());
            }
            Gui.endTable();
        }
    }

    @Override
    void directCamera(CourseScene scene, float dt, float aspect) {
        if (over()) scene.overview(dt, aspect);
        else super.directCamera(scene, dt, aspect);
    }

    @Override
    boolean showsFinalCard() {
        return over();
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        if (over()) app.toMainMenu();
        return true;
    }
}
