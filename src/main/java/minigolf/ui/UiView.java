package minigolf.ui;

import java.nio.file.Path;
import java.util.List;
import minigolf.game.BallReadout;
import minigolf.game.BotTurn;
import minigolf.game.Game;
import minigolf.game.UserSettings;
import minigolf.physics.World;

/** What the screens show; read on the render thread. */
public interface UiView {
    World world();

    /** The game being played, or null. */
    Game game();

    /** The ball under the HUD: the rolling one, else the current player's. */
    BallReadout readout();

    /** The bot deciding now, or null. */
    BotTurn botTurn();

    /** A course point (x, y) on the terrain in HUD pixels, or null when off screen (for the bot's plan). */
    default float[] toScreen(double x, double y) {
        return null;
    }

    UserSettings settings();

    /** The courses to choose from: (name, file). */
    List<CourseEntry> courses();

    List<Path> savedGames();

    /** A one-line message for the player (errors, "saved to ..."), or null. */
    String message();

    /**
     * A notice that stays until the player dismisses it (a broken settings file that was ignored),
     * or null.
     */
    default String notice() {
        return null;
    }

    /** The aim being dragged: speed in m/s, or negative when not aiming. */
    double aimSpeed();

    /** The loft chosen for the next stroke in degrees (0 = a putt; {@link minigolf.game.Loft}). */
    default int loftDegrees() {
        return 0;
    }

    /** GL texture of a course's preview (top row first), or 0 while it is not rendered yet. */
    int thumbnail(CourseEntry course);

    record CourseEntry(String name, Path file, boolean own) {
    }

    /** The round being played, or null (a single course). */
    minigolf.game.RoundGame round();

    /** The round the next game plays, or null (the selected course). */
    minigolf.game.Round chosenRound();

    /** "Replay: stroke 2 of 5 - Ann" while a replay runs, else null. */
    String replayCaption();

    /** The volumes. */
    minigolf.game.AudioSettings volumes();

    /** Scores kept between games, or null when the score file could not be read. */
    minigolf.game.HighScores highScores();

    /** The rounds to choose from (loaded, so they can be played). */
    List<RoundEntry> rounds();

    record RoundEntry(minigolf.game.Round round, Path file) {
    }
}
