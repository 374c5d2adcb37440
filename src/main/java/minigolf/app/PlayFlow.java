package minigolf.app;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.CourseException;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SavedRounds;
import minigolf.game.StrokeAnimator;
import minigolf.game.UserSettings;
import minigolf.physics.World;
import minigolf.ui.Screen;

/**
 * What is being played and how it changes: a single course or a round, its holes one after the
 * other, a saved game or round resumed, back to the menu. Each change stops a thinking bot first
 * and shows the course it leads to.
 */
final class PlayFlow {
    private final GameApp app;

    PlayFlow(GameApp app) {
        this.app = app;
    }

    /** A game on the chosen course, or the chosen round, for these players. */
    void startGame(List<Player> players) {
        if (app.roundToPlay != null) {
            startRound(app.roundToPlay, players);
            return;
        }
        stopPlay();
        app.round = null;
        UserSettings s = app.settings;
        // The "realistic" noise, drawn from a new seed each game (saved with the game, so a resumed game goes on alike).
        app.game = new Game(app.world, s.simulation(), players, s.strokeLimit(), s.noise(), System.nanoTime());
        app.camera.reset();
        app.screens.show(Screen.PLAYING);
        app.say(players.get(0).name() + " tees off. Drag back from the ball to aim; ESC pauses.");
    }

    void startRound(Round r, List<Player> players) {
        stopPlay();
        UserSettings s = app.settings;
        app.round = new RoundGame(r, s.simulation(), players, s.strokeLimit(), s.noise(), System.nanoTime());
        showHole();
        app.say(r.name() + ", hole 1 of " + r.size() + " (par " + r.hole(0).par() + "): " + players.get(0).name() + " tees off.");
    }

    /** The round's next hole, or its final card after the last. */
    void nextHole() {
        RoundGame round = app.round;
        if (round == null) return;
        if (round.isHoleOver()) app.files.recordScores(round, round.finishHole());
        if (!round.nextHole()) {
            app.screens.show(Screen.ROUND_CARD);
            return;
        }
        stopPlay();
        showHole();
        app.say("Hole " + (round.holeIndex() + 1) + " of " + round.round().size() + ": " + app.world.course().name()
                + ", par " + round.hole().par());
    }

    /** Plays a course file from now on (single games); a broken file is said and changes nothing. */
    void selectCourse(Path file) {
        try {
            app.world = World.load(file);
            app.coursePath = file;
            app.roundToPlay = null;
            app.round = null;
            app.game = null;
            app.animator = null;
            app.rebuildScene = true;
            app.screens.show(Screen.MAIN_MENU);
            app.say("course: " + app.world.course().name());
        } catch (CourseException e) {
            app.say(e.getMessage());
        }
    }

    /** Resumes a saved round or game where it was left, a stroke in flight included. */
    void load(Path file) {
        try {
            SavedRounds.AnySave save = SavedRounds.loadAny(file);
            stopPlay();
            if (save.round() != null) {
                app.round = save.round();
                app.roundToPlay = app.round.round();
                showHole();
                resumeStroke();
                if (app.game.isOver()) app.screens.show(Screen.ROUND_CARD);
                app.say("loaded " + file.getFileName() + ": " + app.round.round().name() + ", hole " + (app.round.holeIndex() + 1));
                return;
            }
            SavedGames.Loaded loaded = save.game();
            app.round = null;
            app.world = loaded.world();
            app.buildScene();
            app.game = loaded.resume();
            resumeStroke();
            app.screens.show(app.game.isOver() ? Screen.SCORECARD : Screen.PLAYING);
            app.say("loaded " + file.getFileName());
        } catch (SaveGameException e) {
            app.say(e.getMessage());
        }
    }

    void toMainMenu() {
        stopPlay();
        app.game = null;
        app.round = null;
        app.screens.show(Screen.MAIN_MENU);
    }

    /** Shows the round's current hole: its course, a fresh camera, the HUD. */
    private void showHole() {
        app.game = app.round.game();
        app.world = app.game.world();
        app.coursePath = null;
        app.buildScene();
        app.screens.show(Screen.PLAYING);
    }

    /** A saved stroke still rolling goes on rolling. */
    private void resumeStroke() {
        Game g = app.game;
        app.animator = g.isShotInFlight() ? new StrokeAnimator(g.activeStroke(), g.settings().dt()) : null;
    }

    /** The bot thinking now stops and the rolling animation is dropped. */
    private void stopPlay() {
        app.cancelBot();
        app.botTurn = null;
        app.animator = null;
    }
}
